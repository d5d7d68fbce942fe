#pragma once
// Which pixels adaptive sampling stops (docs/sampling.md, "Adaptive sampling"), in the style of
// Cycles': a pixel stops when the error estimate of its 3x3 neighbourhood is at most its
// threshold, and only when every pixel around it that still takes samples could stop too, so that
// a pixel whose own estimate is low by chance inside a noisy region is not frozen. Unlike Cycles',
// the threshold is not the same for every pixel: a pixel stops when its next samples would buy
// less error per sample than the image needs (marginalStopThreshold), which spends the samples
// where they lower the image's error most. No OpenGL: the rule is unit tested on plain arrays.

#include <cstdint>
#include <limits>
#include <vector>

namespace ptview {

struct AdaptiveStopInput {
    int width = 0, height = 0;
    // Per pixel, rows top first: its estimated relative MSE (PixelErrorTerms::relativeMse; a
    // stopped pixel keeps its last), its sample count, and whether it still takes samples.
    const std::vector<double>* pixelRelativeMse = nullptr;
    const std::vector<int>* pixelSampleCounts = nullptr;
    const std::vector<std::uint8_t>* pixelTakesSamples = nullptr;
    // A pixel's threshold is this times its sample count: the relative MSE per sample its error
    // must fall to (marginalStopThreshold). With every pixel at the same count n, this is the
    // plain threshold divided by n.
    double thresholdRelativeMsePerSample = 0.0;
    // No pixel's threshold exceeds this (relative MSE; infinity: no bound).
    double maxThresholdRelativeMse = std::numeric_limits<double>::infinity();
    int minSamples = 0;                // no pixel stops before it has these
    // Pixels stop in whole tiles of tileSide x tileSide, counted from the image's bottom-left
    // corner (where OpenGL's rasterizer aligns its blocks): a GPU or llvmpipe runs the pixels of a
    // block together, and a block with one pixel still sampled costs as much as a full one.
    int tileSide = 1;
};

// The mean of pixelRelativeMse over each pixel's 3x3 neighbourhood (clipped at the border), rows
// top first: the error the rule judges a pixel by.
std::vector<double> neighbourhoodRelativeMse(const AdaptiveStopInput& input);

// A pixel "could stop" when it takes samples, has at least minSamples, and its
// neighbourhoodRelativeMse is at most thresholdRelativeMsePerSample times its sample count, and
// at most maxThresholdRelativeMse.
// It stops when it and every pixel of its 3x3 neighbourhood that still takes samples could, and
// so does every pixel of its tile that still takes samples. Returns the flags of the pixels that
// stop now (1), rows top first.
std::vector<std::uint8_t> pixelsToStop(const AdaptiveStopInput& input);

// The threshold per sample mu that spends the fewest samples on reaching an image whose mean
// relative MSE is targetRelativeMse. A pixel's error e falls as v / n with its samples n (v its
// relative variance per sample, estimated as e n); the last sample a pixel takes lowers it by
// about e / n, so the total is least when every pixel stops where e / n falls to the same mu
// (then n = sqrt(v / mu): samples in proportion to the square root of the variance, where an
// equal threshold for all, n = v / E^2, spends them in proportion to the variance and gains
// nothing over uniform sampling in the mean). mu is where the image's predicted final error,
// stopped pixels at their kept error and the others at min(e, sqrt(v mu)), equals the target:
// 0 when the stopped pixels alone exceed it, infinity when the image is there already.
// `relativeMse` is neighbourhoodRelativeMse's; the input's threshold per sample is not read, its
// maxThresholdRelativeMse is.
double marginalStopThreshold(const AdaptiveStopInput& input, const std::vector<double>& relativeMse,
                             double targetRelativeMse);

} // namespace ptview
