#pragma once
// How far a progressive render still is from converged, judged from the image alone: each
// pixel's variance of the mean (from its own samples) against the image's brightness. No
// reference is needed, so the viewer can show it live; it measures noise, not bias.

#include "Accumulator.h"

namespace ptview {

struct ErrorEstimate {
    // sqrt(mean over pixels of Var[mean] / (mean^2 + 1e-4)), with each pixel's mean and variance
    // averaged over its channels: the RMS of each pixel's standard error relative to its own
    // value, the square root of the usual relative MSE. The 1e-4 (a radiance of 0.01 squared)
    // keeps nearly black pixels from dominating. Halves when the samples quadruple; 0 before two.
    double relativeError = 0.0;
    long long nonFinitePixels = 0; // pixels whose mean is NaN or infinite (left out of the above)
};

ErrorEstimate estimateError(const PixelStatistics& statistics);

} // namespace ptview
