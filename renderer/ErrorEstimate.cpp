#include "ErrorEstimate.h"

#include <cmath>

namespace ptview {

ErrorEstimate estimateError(const PixelStatistics& statistics) {
    ErrorEstimate estimate;
    constexpr double kDarkRadianceSquared = 1e-4;
    double sumRelativeVariance = 0.0;
    long long finitePixels = 0;
    for (int y = 0; y < statistics.mean.height; ++y) {
        for (int x = 0; x < statistics.mean.width; ++x) {
            glm::vec3 mean = statistics.mean.at(x, y);
            glm::vec3 variance = statistics.varianceOfMean.at(x, y);
            bool finite = true;
            for (int c = 0; c < 3; ++c) finite = finite && std::isfinite(mean[c]) && std::isfinite(variance[c]);
            if (!finite) {
                ++estimate.nonFinitePixels;
                continue;
            }
            double pixelMean = (double(mean.r) + mean.g + mean.b) / 3.0;
            double pixelVariance = (double(variance.r) + variance.g + variance.b) / 3.0;
            sumRelativeVariance += pixelVariance / (pixelMean * pixelMean + kDarkRadianceSquared);
            ++finitePixels;
        }
    }
    if (statistics.sampleCount < 2 || finitePixels == 0) return estimate;
    estimate.relativeError = std::sqrt(sumRelativeVariance / static_cast<double>(finitePixels));
    return estimate;
}

} // namespace ptview
