#include "ErrorEstimate.h"

#include <vector>

namespace ptview {
namespace {

bool finitePixel(const ImageRgbF& image, int x, int y) {
    glm::vec3 v = image.at(x, y);
    return std::isfinite(v.r) && std::isfinite(v.g) && std::isfinite(v.b);
}

// Mean of the finite pixels in the 3x3 neighbourhood (clipped at the border), per channel.
glm::dvec3 neighbourhoodMean(const ImageRgbF& image, int x, int y) {
    glm::dvec3 sum(0.0);
    int count = 0;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= image.width || ny >= image.height || !finitePixel(image, nx, ny)) continue;
            sum += glm::dvec3(image.at(nx, ny));
            ++count;
        }
    }
    return count > 0 ? sum / double(count) : glm::dvec3(0.0);
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
    double sum = 0.0, sumSquares = 0.0;
    long long terms = 0;
    for (int y = 0; y < mean.height; ++y) {
        for (int x = 0; x < mean.width; ++x) {
            if (!finitePixel(mean, x, y) || !finitePixel(statistics.varianceOfMean, x, y) ||
                !finitePixel(earlierMean, x, y))
                continue;
            glm::vec3 now = mean.at(x, y), before = earlierMean.at(x, y), variance = statistics.varianceOfMean.at(x, y);
            glm::dvec3 around = neighbourhoodMean(mean, x, y);
            for (int c = 0; c < 3; ++c) {
                double change = double(now[c]) - double(before[c]);
                double meanSquared = std::max(double(now[c]) * now[c] - double(variance[c]), around[c] * around[c]);
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
