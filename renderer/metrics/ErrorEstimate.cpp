#include "ErrorEstimate.h"

#include <vector>

namespace ptview {
namespace {

bool finitePixel(const ImageRgbF& image, int x, int y) {
    glm::vec3 v = image.at(x, y);
    return std::isfinite(v.r) && std::isfinite(v.g) && std::isfinite(v.b);
}

// Mean of the finite pixels in each pixel's 3x3 neighbourhood (clipped at the border), per
// channel: separable running sums, so a full-window image costs a few milliseconds once a second.
ImageRgbF neighbourhoodMeans(const ImageRgbF& image) {
    const int w = image.width, h = image.height;
    // Four doubles per pixel: the finite pixels' r, g, b sums and their count.
    std::vector<double> values(size_t(w) * h * 4, 0.0), rows(values.size(), 0.0);
    for (size_t i = 0; i < size_t(w) * h; ++i) {
        const float* rgb = &image.rgb[3 * i];
        if (!std::isfinite(rgb[0]) || !std::isfinite(rgb[1]) || !std::isfinite(rgb[2])) continue;
        for (int c = 0; c < 3; ++c) values[4 * i + c] = rgb[c];
        values[4 * i + 3] = 1.0;
    }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            size_t i = size_t(y) * w + x;
            for (int k = 0; k < 4; ++k)
                rows[4 * i + k] = values[4 * i + k] + (x > 0 ? values[4 * (i - 1) + k] : 0.0) +
                                  (x + 1 < w ? values[4 * (i + 1) + k] : 0.0);
        }
    ImageRgbF means(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            size_t i = size_t(y) * w + x;
            double sum[4];
            for (int k = 0; k < 4; ++k)
                sum[k] = rows[4 * i + k] + (y > 0 ? rows[4 * (i - w) + k] : 0.0) + (y + 1 < h ? rows[4 * (i + w) + k] : 0.0);
            if (sum[3] > 0.0)
                for (int c = 0; c < 3; ++c) means.rgb[3 * i + c] = float(sum[c] / sum[3]);
        }
    return means;
}

} // namespace

ErrorEstimate estimateError(const PixelStatistics& statistics, const ImageRgbF& earlierMean, int earlierSamples,
                            SamplerMode sampler) {
    ErrorEstimate estimate;
    const ImageRgbF& mean = statistics.mean;
    for (int y = 0; y < mean.height; ++y)
        for (int x = 0; x < mean.width; ++x)
            if (!finitePixel(mean, x, y) || !finitePixel(statistics.varianceOfMean, x, y)) ++estimate.nonFinitePixels;
    if (sampler == SamplerMode::Grid) {
        estimate.unreliableReason = "the grid sampler repeats one pattern in every pixel: how its image changes is not "
                                    "noise, and its error is bias, which no estimate from the render can see";
        return estimate;
    }
    int n = statistics.sampleCount;
    if (earlierSamples < 1 || 2 * earlierSamples > n || earlierMean.width != mean.width ||
        earlierMean.height != mean.height)
        return estimate;
    // E[(x_n - x_m)^2] = Var[x_m] - Var[x_n] = Var[x_n] (n/m - 1) for independent samples.
    const double varianceScale = 1.0 / (double(n) / double(earlierSamples) - 1.0);
    const ImageRgbF around = neighbourhoodMeans(mean);
    double sum = 0.0, sumSquares = 0.0;
    long long terms = 0;
    for (int y = 0; y < mean.height; ++y) {
        for (int x = 0; x < mean.width; ++x) {
            if (!finitePixel(mean, x, y) || !finitePixel(statistics.varianceOfMean, x, y) ||
                !finitePixel(earlierMean, x, y))
                continue;
            glm::vec3 now = mean.at(x, y), before = earlierMean.at(x, y), variance = statistics.varianceOfMean.at(x, y);
            glm::vec3 aroundHere = around.at(x, y);
            for (int c = 0; c < 3; ++c) {
                double change = double(now[c]) - double(before[c]);
                double meanSquared = std::max(double(now[c]) * now[c] - double(variance[c]), double(aroundHere[c]) * aroundHere[c]);
                double term = change * change * varianceScale / (meanSquared + kRelativeMseEpsilon);
                sum += term;
                sumSquares += term * term;
                ++terms;
            }
        }
    }
    if (terms == 0) return estimate;
    estimate.relativeMse = sum / double(terms);
    if (sum <= 0.0) {
        estimate.unreliableReason = "nothing has changed yet (no light found, or a black image)";
        return estimate;
    }
    estimate.effectivePixels = sum * sum / sumSquares;
    estimate.reliable = estimate.effectivePixels >= kMinEffectivePixels;
    if (!estimate.reliable)
        estimate.unreliableReason = "too few pixels carry the estimate yet (a few bright samples dominate it)";
    return estimate;
}

} // namespace ptview
