#pragma once
// Which pixels adaptive sampling stops (docs/sampling.md, "Adaptive sampling"), in the style of
// Cycles': a pixel stops when the error estimate of its 3x3 neighbourhood is at most the threshold,
// and only when every pixel around it that still takes samples could stop too, so that a pixel
// whose own estimate is low by chance inside a noisy region is not frozen. No OpenGL: the rule
// is unit tested on plain arrays.

#include <cstdint>
#include <vector>

namespace ptview {

struct AdaptiveStopInput {
    int width = 0, height = 0;
    // Per pixel, rows top first: its estimated relative MSE (PixelErrorTerms::relativeMse; a
    // stopped pixel keeps its last), its sample count, and whether it still takes samples.
    const std::vector<double>* pixelRelativeMse = nullptr;
    const std::vector<int>* pixelSampleCounts = nullptr;
    const std::vector<std::uint8_t>* pixelTakesSamples = nullptr;
    double thresholdRelativeMse = 0.0; // the noise threshold squared
    int minSamples = 0;                // no pixel stops before it has these
    // Pixels stop in whole tiles of tileSide x tileSide, counted from the image's bottom-left
    // corner (where OpenGL's rasterizer aligns its blocks): a GPU or llvmpipe runs the pixels of a
    // block together, and a block with one pixel still sampled costs as much as a full one.
    int tileSide = 1;
};

// A pixel "could stop" when it takes samples, has at least minSamples, and the mean of
// pixelRelativeMse over its 3x3 neighbourhood (clipped at the border) is at most the threshold.
// It stops when it and every pixel of its 3x3 neighbourhood that still takes samples could, and
// so does every pixel of its tile that still takes samples. Returns the flags of the pixels that
// stop now (1), rows top first.
std::vector<std::uint8_t> pixelsToStop(const AdaptiveStopInput& input);

} // namespace ptview
