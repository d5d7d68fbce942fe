// The rule adaptive sampling stops pixels by (renderer/metrics/AdaptiveStopRule.h), on plain arrays:
// exactly the pixels the rule names stop, no others.
#include <ptview/metrics/AdaptiveStopRule.h>

#include <gtest/gtest.h>

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
    std::vector<std::uint8_t> stop(double threshold, int minSamples) const {
        AdaptiveStopInput input;
        input.width = width;
        input.height = height;
        input.pixelRelativeMse = &error;
        input.pixelSampleCounts = &counts;
        input.pixelTakesSamples = &takesSamples;
        input.thresholdRelativeMse = threshold;
        input.minSamples = minSamples;
        return pixelsToStop(input);
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
    AdaptiveStopInput input;
    input.width = input.height = 6;
    input.pixelRelativeMse = &field.error;
    input.pixelSampleCounts = &field.counts;
    input.pixelTakesSamples = &field.takesSamples;
    input.thresholdRelativeMse = 1e-4;
    input.minSamples = 16;
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

TEST(AdaptiveStopRule, RefusesArraysOfTheWrongSize) {
    Field field(4, 4, 0.0, 64);
    field.counts.pop_back();
    EXPECT_THROW(field.stop(1e-4, 16), std::invalid_argument);
}

} // namespace
} // namespace ptview
