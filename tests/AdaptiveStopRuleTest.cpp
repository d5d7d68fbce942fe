// The rule adaptive sampling stops pixels by (renderer/metrics/AdaptiveStopRule.h), on plain arrays:
// exactly the pixels the rule names stop, no others.
#include <ptview/metrics/AdaptiveStopRule.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ptview {
namespace {

struct Field {
    int width, height;
    std::vector<double> error;
    std::vector<int> counts;
    std::vector<std::uint8_t> takesSamples;
    Field(int w, int h, double e, int n) : width(w), height(h), error(size_t(w * h), e), counts(size_t(w * h), n), takesSamples(size_t(w * h), 1) {}
    size_t at(int x, int y) const { return size_t(y * width + x); }
    AdaptiveStopInput input(int minSamples = 16) const {
        AdaptiveStopInput input;
        input.width = width;
        input.height = height;
        input.pixelRelativeMse = &error;
        input.pixelSampleCounts = &counts;
        input.pixelTakesSamples = &takesSamples;
        input.minSamples = minSamples;
        return input;
    }
    std::vector<std::uint8_t> stop(double threshold, int minSamples) const {
        AdaptiveStopInput rule = input(minSamples);
        rule.thresholdRelativeMsePerSample = threshold / counts[0]; // equal counts: the plain threshold
        return pixelsToStop(rule);
    }
};

TEST(AdaptiveStopRule, AConvergedImageStopsEverywhereAndANoisyOneNowhere) {
    Field converged(7, 5, 0.5e-4, 32);
    for (std::uint8_t s : converged.stop(1e-4, 16)) EXPECT_EQ(s, 1);
    Field noisy(7, 5, 2e-4, 32);
    for (std::uint8_t s : noisy.stop(1e-4, 16)) EXPECT_EQ(s, 0);
}

TEST(AdaptiveStopRule, NoPixelStopsBeforeTheMinimumSamples) {
    Field field(6, 6, 0.0, 15);
    for (std::uint8_t s : field.stop(1e-4, 16)) EXPECT_EQ(s, 0);
    // Pixels with enough samples around (2, 2): only it has no neighbour held back by the minimum.
    for (int y = 1; y <= 3; ++y)
        for (int x = 1; x <= 3; ++x) field.counts[field.at(x, y)] = 16;
    std::vector<std::uint8_t> stop = field.stop(1e-4, 16);
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 6; ++x) EXPECT_EQ(stop[field.at(x, y)], x == 2 && y == 2 ? 1 : 0) << x << " " << y;
}

// One noisy pixel keeps its whole 5x5 surroundings sampling: the 3x3 mean around each pixel of
// its 3x3 neighbourhood exceeds the threshold (they could not stop), and the ring around those
// has a neighbour that could not stop. Everything further out stops.
TEST(AdaptiveStopRule, ANoisyPixelKeepsItsNeighbourhoodSampling) {
    Field field(11, 11, 0.0, 64);
    field.error[field.at(5, 5)] = 9.0 * 1e-4 * 1.01; // its 3x3 mean is just above the threshold
    std::vector<std::uint8_t> stop = field.stop(1e-4, 16);
    for (int y = 0; y < 11; ++y)
        for (int x = 0; x < 11; ++x) {
            const bool within5x5 = std::abs(x - 5) <= 2 && std::abs(y - 5) <= 2;
            EXPECT_EQ(stop[field.at(x, y)], within5x5 ? 0 : 1) << x << " " << y;
        }
    // At the threshold exactly, every 3x3 mean is at most it: all stop.
    field.error[field.at(5, 5)] = 9.0 * 1e-4;
    for (std::uint8_t s : field.stop(1e-4, 16)) EXPECT_EQ(s, 1);
}

// A pixel whose own estimate is 0 by chance inside a noisy region does not stop: its
// neighbourhood's mean is high.
TEST(AdaptiveStopRule, ALuckyPixelInsideANoisyRegionIsNotFrozen) {
    Field field(9, 9, 1e-3, 64);
    field.error[field.at(4, 4)] = 0.0;
    for (std::uint8_t s : field.stop(1e-4, 16)) EXPECT_EQ(s, 0);
}

// Pixels already stopped neither stop again nor hold their neighbours back, and their kept error
// still counts in the neighbourhood mean.
TEST(AdaptiveStopRule, StoppedPixelsCountByTheirKeptErrorAndHoldNobodyBack) {
    Field field(5, 1, 0.0, 64);
    // Pixel 0 stopped long ago with an error the threshold allowed then; pixel 1 is converged.
    field.takesSamples[0] = 0;
    field.error[0] = 1e-4;
    std::vector<std::uint8_t> stop = field.stop(1e-4, 16);
    EXPECT_EQ(stop[0], 0) << "already stopped: not reported again";
    for (int x = 1; x < 5; ++x) EXPECT_EQ(stop[size_t(x)], 1) << x;
    // A stopped pixel's kept error above the threshold raises its neighbours' means.
    field.error[0] = 3e-4 * 1.01; // pixel 1's 3x1 mean: (3.03e-4 + 0 + 0) / 3 > 1e-4
    stop = field.stop(1e-4, 16);
    EXPECT_EQ(stop[1], 0);
    EXPECT_EQ(stop[2], 0) << "its neighbour 1 could not stop";
    EXPECT_EQ(stop[3], 1);
    EXPECT_EQ(stop[4], 1);
}

// Tiles stop whole, aligned from the bottom-left corner as the rasterizer's blocks are: on a 6x6
// image with tiles of 4, the bottom-left tile is rows 2..5 from the top, columns 0..3.
TEST(AdaptiveStopRule, TilesStopOnlyWhole) {
    Field field(6, 6, 0.0, 64);
    field.takesSamples[field.at(5, 0)] = 0; // a stopped pixel holds no tile back
    std::vector<std::uint8_t> stop = field.stop(1e-4, 16);
    AdaptiveStopInput input = field.input(16);
    input.thresholdRelativeMsePerSample = 1e-4 / 64;
    input.tileSide = 4;
    for (size_t i = 0; i < stop.size(); ++i) EXPECT_EQ(pixelsToStop(input)[i], stop[i]) << "all converged: as without tiles";
    // Pixel (0, 0) (top left) cannot stop (too few samples), which holds back (1, 0), (0, 1) and
    // (1, 1) by the neighbourhood rule, all in the top-left tile (rows 0..1, columns 0..3): that
    // whole tile keeps sampling; the tile below it (rows 2..5) stops whole.
    field.counts[field.at(0, 0)] = 8;
    stop = pixelsToStop(input);
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 6; ++x) {
            const bool topLeftTile = y <= 1 && x <= 3, alreadyStopped = x == 5 && y == 0;
            EXPECT_EQ(stop[field.at(x, y)], topLeftTile || alreadyStopped ? 0 : 1) << x << " " << y;
        }
    // Without tiles only the four pixels the neighbourhood rule holds back keep sampling.
    input.tileSide = 1;
    stop = pixelsToStop(input);
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 6; ++x)
            EXPECT_EQ(stop[field.at(x, y)], (x <= 1 && y <= 1) || (x == 5 && y == 0) ? 0 : 1) << x << " " << y;
}

// A pixel's threshold grows with its samples: at the same error, the pixel with more samples (whose
// next samples buy less) stops, the other does not.
TEST(AdaptiveStopRule, APixelsThresholdIsPerSample) {
    Field field(8, 8, 1e-4, 64);
    for (int y = 0; y < 8; ++y)
        for (int x = 4; x < 8; ++x) field.counts[field.at(x, y)] = 256;
    AdaptiveStopInput input = field.input(16);
    input.thresholdRelativeMsePerSample = 1e-4 / 128; // 0.5e-4 at 64 samples, 2e-4 at 256
    std::vector<std::uint8_t> stop = pixelsToStop(input);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) EXPECT_EQ(stop[field.at(x, y)], x >= 5 ? 1 : 0) << x << " " << y; // x = 4: held by x = 3
}

// Pixels whose errors fall as v / n, checked every 1.1x samples (AdaptiveSampler's
// kAdaptiveCheckGrowth; the rule's properties hold for any such schedule): the
// marginal threshold gives the noisier half sqrt(100) = 10 times the samples of the other half
// (an equal threshold would give it 100 times), reaches the target error, and spends 0.6x the
// samples an equal threshold spends for it ((1 + 10)^2 / 4 / ((1 + 100) / 2)).
TEST(AdaptiveStopRule, TheMarginalThresholdSpendsSamplesAsTheSquareRootOfTheVariance) {
    const int w = 32, h = 8;
    const double target = 1e-4;
    Field field(w, h, 0.0, 64);
    std::vector<double> variancePerSample(size_t(w * h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) variancePerSample[field.at(x, y)] = x < w / 2 ? 1.0 : 0.01;
    AdaptiveStopInput input = field.input(64);
    int checks = 0;
    for (; checks < 100; ++checks) {
        bool anySampled = false;
        for (size_t i = 0; i < field.error.size(); ++i)
            if (field.takesSamples[i]) {
                field.error[i] = variancePerSample[i] / field.counts[i];
                anySampled = true;
            }
        if (!anySampled) break;
        std::vector<double> neighbourhood = neighbourhoodRelativeMse(input);
        input.thresholdRelativeMsePerSample = marginalStopThreshold(input, neighbourhood, target);
        std::vector<std::uint8_t> stop = pixelsToStop(input);
        for (size_t i = 0; i < stop.size(); ++i) {
            if (stop[i]) field.takesSamples[i] = 0;
            if (field.takesSamples[i]) field.counts[i] = int(std::ceil(field.counts[i] * 1.1));
        }
    }
    ASSERT_LT(checks, 100);
    double meanError = 0.0, samples = 0.0, equalThresholdSamples = 0.0;
    for (size_t i = 0; i < field.error.size(); ++i) {
        meanError += field.error[i] / field.error.size();
        samples += field.counts[i];
        equalThresholdSamples += std::max(64.0, variancePerSample[i] / target);
    }
    EXPECT_LE(meanError, target * 1.02);
    EXPECT_GE(meanError, target * 0.75) << "not far past it either";
    EXPECT_LT(samples, 0.7 * equalThresholdSamples);
    // Away from the border between the halves (where 3x3 means mix them), the counts' ratio is
    // sqrt(100), to within a check's step.
    const double ratio = double(field.counts[field.at(2, 4)]) / field.counts[field.at(w - 3, 4)];
    EXPECT_GT(ratio, 10.0 / 1.3);
    EXPECT_LT(ratio, 10.0 * 1.3);
}

// However many samples a pixel has, its threshold is at most maxThresholdRelativeMse.
TEST(AdaptiveStopRule, NoPixelsThresholdExceedsTheBound) {
    Field field(8, 8, 4e-4, 4096);
    AdaptiveStopInput input = field.input(16);
    input.thresholdRelativeMsePerSample = 1e-6; // 4.1e-3 at 4096 samples
    for (std::uint8_t s : pixelsToStop(input)) EXPECT_EQ(s, 1) << "unbounded";
    input.maxThresholdRelativeMse = 3.9e-4;
    for (std::uint8_t s : pixelsToStop(input)) EXPECT_EQ(s, 0) << "above the bound";
    // The prediction knows the bound: a pixel still sampled ends at most there.
    input.maxThresholdRelativeMse = 1e-4;
    const double mu = marginalStopThreshold(input, field.error, 2e-4);
    EXPECT_TRUE(std::isinf(mu)) << "every pixel would end at 1e-4 at most: the target is met whatever mu";
}

TEST(AdaptiveStopRule, MarginalThresholdAtTheEnds) {
    Field field(4, 4, 1e-4, 64);
    AdaptiveStopInput input = field.input();
    EXPECT_TRUE(std::isinf(marginalStopThreshold(input, field.error, 1.01e-4))) << "there already: every pixel may stop";
    EXPECT_GT(marginalStopThreshold(input, field.error, 0.5e-4), 0.0);
    for (auto& flag : field.takesSamples) flag = 0;
    EXPECT_EQ(marginalStopThreshold(input, field.error, 0.5e-4), 0.0) << "the stopped pixels alone exceed it";
}

TEST(AdaptiveStopRule, RefusesArraysOfTheWrongSize) {
    Field field(4, 4, 0.0, 64);
    field.counts.pop_back();
    EXPECT_THROW(field.stop(1e-4, 16), std::invalid_argument);
}

} // namespace
} // namespace ptview
