#include <ptview/metrics/ErrorEstimate.h>

#include <ptview/metrics/NonFinitePixels.h>

#include <iterator>
#include <vector>

namespace ptview {
namespace {

// Sums of the finite pixels' means, variances of the mean and count over any rectangle, from
// summed-area tables: each pixel's neighbourhoods of several sizes cost a few lookups, so the
// viewer can afford a full-window estimate once a second (docs/performance.md, "Measurements
// behind code comments").
class NeighbourhoodSums {
public:
    NeighbourhoodSums(const ImageRgbF& mean, const ImageRgbF& varianceOfMean)
        : width_(mean.width), height_(mean.height), table_(size_t(width_ + 1) * (height_ + 1) * kValues, 0.0) {
        for (int y = 0; y < height_; ++y)
            for (int x = 0; x < width_; ++x) {
                double values[kValues] = {};
                if (isFinitePixel(mean.at(x, y)) && isFinitePixel(varianceOfMean.at(x, y))) {
                    glm::vec3 m = mean.at(x, y), v = varianceOfMean.at(x, y);
                    for (int c = 0; c < 3; ++c) {
                        values[c] = m[c];
                        values[3 + c] = v[c];
                    }
                    values[6] = 1.0;
                }
                for (int k = 0; k < kValues; ++k)
                    at(x + 1, y + 1)[k] = values[k] + at(x, y + 1)[k] + at(x + 1, y)[k] - at(x, y)[k];
            }
    }

    // The mean of the finite pixels' means within `radius` of (x, y) (clipped at the border), and
    // the variance of that mean (pixels are independent): sum Var / count^2.
    void around(int x, int y, int radius, glm::dvec3& mean, glm::dvec3& varianceOfMean) const {
        int x0 = std::max(x - radius, 0), x1 = std::min(x + radius + 1, width_);
        int y0 = std::max(y - radius, 0), y1 = std::min(y + radius + 1, height_);
        double sum[kValues];
        for (int k = 0; k < kValues; ++k) sum[k] = at(x1, y1)[k] - at(x0, y1)[k] - at(x1, y0)[k] + at(x0, y0)[k];
        double count = std::max(sum[6], 1.0);
        mean = glm::dvec3(sum[0], sum[1], sum[2]) / count;
        varianceOfMean = glm::dvec3(sum[3], sum[4], sum[5]) / (count * count);
    }

private:
    static constexpr int kValues = 7; // r, g, b means; r, g, b variances of the mean; finite count
    double* at(int x, int y) { return &table_[(size_t(y) * (width_ + 1) + x) * kValues]; }
    const double* at(int x, int y) const { return &table_[(size_t(y) * (width_ + 1) + x) * kValues]; }
    int width_, height_;
    std::vector<double> table_;
};

// The neighbourhood half-widths tried, smallest first: the pixel alone, 3x3, 5x5, 9x9, 17x17.
constexpr int kNeighbourhoodRadii[] = {0, 1, 2, 4, 8};
// A neighbourhood's squared mean is used once its standard error is at most this share of
// mean^2 + epsilon (the relative error it adds to the estimate is about half that).
constexpr double kConvergedBrightnessRelativeError = 0.25;
// A pixel's own mean is its brightness (in the second estimate) once mean^2 >= this * Var[mean]:
// about three samples' worth of it, where a firefly (one or two bright samples) gives 1 to 2.
constexpr double kOwnMeanSamples = 3.0;
// The two estimates differ by more than this (relative MSE; 2x in relative error) where a few
// pixels' rare bright samples decide the answer: no number then.
constexpr double kMaxDenominatorDisagreement = 4.0;

// mean^2 + epsilon of the image the pixel converges to, estimated two ways (see the header): the
// pixel's own unbiased mean^2 as a floor under its neighbourhood's, and the pixel's own mean alone
// once kOwnMeanSamples samples' worth carry it, else its neighbourhood's.
struct ConvergedBrightness {
    glm::dvec3 ownAsFloor;
    glm::dvec3 ownOnceKnown;
    bool ownKnown[3]; // kOwnMeanSamples samples' worth carry the pixel's own mean
    glm::dvec3 darkest; // its own unbiased mean^2 alone: the least it may converge to
};

ConvergedBrightness convergedBrightness(const NeighbourhoodSums& sums, int x, int y, glm::vec3 ownMean,
                                        glm::vec3 ownVariance) {
    glm::dvec3 own(0.0), neighbourhood(0.0);
    bool settled[3] = {false, false, false};
    for (int c = 0; c < 3; ++c) own[c] = std::max(double(ownMean[c]) * ownMean[c] - double(ownVariance[c]), 0.0);
    for (int radius : kNeighbourhoodRadii) {
        glm::dvec3 mean, variance;
        sums.around(x, y, radius, mean, variance);
        bool widest = radius == kNeighbourhoodRadii[std::size(kNeighbourhoodRadii) - 1];
        for (int c = 0; c < 3; ++c) {
            if (settled[c]) continue;
            double squared = mean[c] * mean[c];
            // Var[X^2] ~ 4 X^2 Var[X]: the standard error of the squared mean.
            bool known = 2.0 * std::abs(mean[c]) * std::sqrt(variance[c]) <=
                         kConvergedBrightnessRelativeError * (squared + kRelativeMseEpsilon);
            if (!known && !widest) continue;
            neighbourhood[c] = std::max(squared - variance[c], 0.0);
            settled[c] = true;
        }
        if (settled[0] && settled[1] && settled[2]) break;
    }
    ConvergedBrightness brightness;
    for (int c = 0; c < 3; ++c) {
        brightness.ownAsFloor[c] = std::max(own[c], neighbourhood[c]) + kRelativeMseEpsilon;
        brightness.darkest[c] = own[c] + kRelativeMseEpsilon;
        // mean^2 / Var[mean]: how many samples' worth carry the mean (one bright sample: about 1).
        brightness.ownKnown[c] = double(ownMean[c]) * ownMean[c] >= kOwnMeanSamples * double(ownVariance[c]);
        brightness.ownOnceKnown[c] = (brightness.ownKnown[c] ? own[c] : neighbourhood[c]) + kRelativeMseEpsilon;
    }
    return brightness;
}

} // namespace

ErrorEstimate estimateError(const PixelStatistics& statistics, const ImageRgbF& earlierMean, int earlierSamples,
                            SamplerMode sampler) {
    ErrorEstimate estimate;
    const ImageRgbF& mean = statistics.mean;
    for (int y = 0; y < mean.height; ++y)
        for (int x = 0; x < mean.width; ++x)
            if (!isFinitePixel(mean.at(x, y)) || !isFinitePixel(statistics.varianceOfMean.at(x, y))) ++estimate.nonFinitePixels;
    if (sampler == SamplerMode::Grid) {
        estimate.unreliableReason = "the grid sampler repeats one pattern in every pixel: how its image changes is not "
                                    "noise, and its error is bias, which no estimate from the render can see";
        return estimate;
    }
    // The image's estimate is the sum of its pixels' terms: the same sums adaptive sampling stops
    // pixels by (pixelErrorTerms, estimateFromPixelTerms).
    ErrorEstimate fromPixels = estimateFromPixelTerms(pixelErrorTerms(statistics, earlierMean, earlierSamples));
    fromPixels.nonFinitePixels = estimate.nonFinitePixels;
    return fromPixels;
}

std::vector<PixelErrorTerms> pixelErrorTerms(const PixelStatistics& statistics, const ImageRgbF& earlierMean,
                                             int earlierSamples) {
    const ImageRgbF& mean = statistics.mean;
    const int n = statistics.sampleCount;
    if (earlierSamples < 1 || 2 * earlierSamples > n || earlierMean.width != mean.width || earlierMean.height != mean.height)
        return {};
    // E[(x_n - x_m)^2] = Var[x_m] - Var[x_n] = Var[x_n] (n/m - 1) for independent samples.
    const double varianceScale = 1.0 / (double(n) / double(earlierSamples) - 1.0);
    const NeighbourhoodSums sums(mean, statistics.varianceOfMean);
    std::vector<PixelErrorTerms> terms(size_t(mean.width) * size_t(mean.height));
    for (int y = 0; y < mean.height; ++y)
        for (int x = 0; x < mean.width; ++x) {
            if (!isFinitePixel(mean.at(x, y)) || !isFinitePixel(statistics.varianceOfMean.at(x, y)) ||
                !isFinitePixel(earlierMean.at(x, y)))
                continue;
            glm::vec3 now = mean.at(x, y), before = earlierMean.at(x, y), variance = statistics.varianceOfMean.at(x, y);
            ConvergedBrightness brightness = convergedBrightness(sums, x, y, now, variance);
            PixelErrorTerms& pixel = terms[size_t(y) * size_t(mean.width) + size_t(x)];
            for (int c = 0; c < 3; ++c) {
                double change = double(now[c]) - double(before[c]);
                // A mean that fewer than kOwnMeanSamples samples' worth carry is known no better than
                // its samples' spread says, however little it changed: a light smaller than the
                // pixel met by the same share of the samples at both reads shows no change at all.
                double squaredError = std::max(change * change * varianceScale,
                                               brightness.ownKnown[c] ? 0.0 : double(variance[c]));
                double term = squaredError / brightness.ownAsFloor[c];
                pixel.ownAsFloor += term;
                pixel.ownAsFloorSquares += term * term;
                pixel.ownOnceKnown += squaredError / brightness.ownOnceKnown[c];
                pixel.ownMeanKnown = pixel.ownMeanKnown && brightness.ownKnown[c];
                pixel.stopRelativeMse += squaredError / (brightness.ownKnown[c] ? brightness.ownOnceKnown[c]
                                                                                : brightness.darkest[c]);
            }
            pixel.channels = 3;
        }
    return terms;
}

ErrorEstimate estimateFromPixelTerms(const std::vector<PixelErrorTerms>& pixels) {
    ErrorEstimate estimate;
    double sum = 0.0, sumSquares = 0.0, sumOwnOnceKnown = 0.0;
    long long terms = 0;
    for (const PixelErrorTerms& pixel : pixels) {
        sum += pixel.ownAsFloor;
        sumSquares += pixel.ownAsFloorSquares;
        sumOwnOnceKnown += pixel.ownOnceKnown;
        terms += pixel.channels;
    }
    if (terms == 0) return estimate;
    if (sum <= 0.0) {
        estimate.unreliableReason = "nothing has changed yet (no light found, or a black image)";
        return estimate;
    }
    // ownOnceKnown's denominators are never larger than ownAsFloor's, so its sum is never smaller.
    estimate.relativeMse = std::sqrt(sum * sumOwnOnceKnown) / double(terms);
    estimate.effectivePixels = sum * sum / sumSquares;
    if (estimate.effectivePixels < kMinEffectivePixels) {
        estimate.unreliableReason = "too few pixels carry the estimate yet (a few bright samples dominate it)";
        return estimate;
    }
    if (sumOwnOnceKnown > kMaxDenominatorDisagreement * sum) {
        estimate.unreliableReason = "pixels whose mean rests on a few bright samples decide it: a firefly or a light "
                                    "smaller than a pixel, which the render cannot tell apart yet";
        return estimate;
    }
    estimate.reliable = true;
    return estimate;
}

} // namespace ptview
