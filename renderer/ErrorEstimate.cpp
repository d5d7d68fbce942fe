#include "ErrorEstimate.h"

#include <cmath>

namespace ptview {

ErrorEstimate estimateError(const PixelStatistics& statistics) {
    ErrorEstimate estimate;
    double sumVariance = 0.0, sumMean = 0.0;
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
            sumVariance += double(variance.r) + variance.g + variance.b;
            sumMean += double(mean.r) + mean.g + mean.b;
            ++finitePixels;
        }
    }
    if (statistics.sampleCount < 2 || finitePixels == 0 || sumMean <= 0.0) return estimate;
    double count = 3.0 * static_cast<double>(finitePixels);
    estimate.relativeError = std::sqrt(sumVariance / count) / (sumMean / count);
    return estimate;
}

} // namespace ptview
