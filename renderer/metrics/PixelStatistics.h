#pragma once
// What the accumulation knows about each pixel, read back as plain images: the error metrics and
// the live error estimate work on these without OpenGL.

#include "Image.h"

namespace ptview {

// Per-pixel mean and the variance of that mean, estimated from the samples themselves.
struct PixelStatistics {
    ImageRgbF mean;
    ImageRgbF varianceOfMean;
    int sampleCount = 0;
};

} // namespace ptview
