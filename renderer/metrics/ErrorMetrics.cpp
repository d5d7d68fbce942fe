#include <ptview/metrics/ErrorMetrics.h>

#include <ptview/io/ImageIO.h>
#include <ptview/metrics/NonFinitePixels.h>

#include <cmath>
#include <limits>
#include <string>

namespace ptview {

ErrorMetrics compareToReference(const ImageRgbF& image, const ImageRgbF& reference) {
    if (image.width != reference.width || image.height != reference.height)
        throw std::invalid_argument("the image is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                    " but the reference is " + std::to_string(reference.width) + "x" +
                                    std::to_string(reference.height));
    ErrorMetrics metrics;
    double squared = 0.0, relative = 0.0;
    glm::dvec3 sumImage(0.0), sumReference(0.0);
    long long finite = 0, nonFinite = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            glm::vec3 value = image.at(x, y), expected = reference.at(x, y);
            if (!isFinitePixel(value)) {
                ++nonFinite;
                continue;
            }
            for (int c = 0; c < 3; ++c) {
                double difference = double(value[c]) - double(expected[c]);
                squared += difference * difference;
                relative += difference * difference / (double(expected[c]) * expected[c] + kRelativeMseEpsilon);
            }
            sumImage += glm::dvec3(value);
            sumReference += glm::dvec3(expected);
            ++finite;
        }
    }
    long long pixels = finite + nonFinite;
    metrics.nonFiniteShare = pixels > 0 ? double(nonFinite) / double(pixels) : 0.0;
    if (finite == 0) {
        constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
        metrics.rmse = metrics.relativeMse = kNaN;
        metrics.meanBias = glm::dvec3(kNaN);
        return metrics;
    }
    metrics.rmse = std::sqrt(squared / (3.0 * double(finite)));
    metrics.relativeMse = relative / (3.0 * double(finite));
    metrics.meanBias = (sumImage - sumReference) / double(finite);
    return metrics;
}

ImageRgbF readReferenceImage(const std::filesystem::path& path) {
    ImageRgbF image = readLinearImage(path);
    const long long nonFinite = countNonFinitePixels(image);
    if (nonFinite == 0) return image;
    int x = 0, y = 0; // the first non-finite pixel, rows from the top
    while (isFinitePixel(image.at(x, y)))
        if (++x == image.width) x = 0, ++y;
    const glm::vec3 value = image.at(x, y);
    const bool nan = std::isnan(value.r) || std::isnan(value.g) || std::isnan(value.b);
    throw std::runtime_error(path.string() + ": pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is " +
                             (nan ? "NaN" : "infinite") + " (" + std::to_string(nonFinite) + " of " +
                             std::to_string(static_cast<long long>(image.width) * image.height) +
                             " pixels are not finite); a reference image must be finite everywhere");
}

} // namespace ptview
