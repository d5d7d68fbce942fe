#pragma once
// How far a progressive render still is from converged, judged from the image alone: each
// pixel's variance of the mean (from its own samples) against the image's brightness. No
// reference is needed, so the viewer can show it live; it measures noise, not bias.

#include "Accumulator.h"

namespace ptview {

struct ErrorEstimate {
    // sqrt(mean over pixels and channels of Var[mean]) / (mean over pixels and channels of the
    // mean): the RMS standard error relative to the image's average value. Halves when the
    // samples per pixel quadruple. 0 before two samples.
    double relativeError = 0.0;
    long long nonFinitePixels = 0; // pixels whose mean is NaN or infinite (left out of the above)
};

ErrorEstimate estimateError(const PixelStatistics& statistics);

} // namespace ptview
