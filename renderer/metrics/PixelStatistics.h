#pragma once
// What the accumulation knows about each pixel, read back as plain images: the error metrics and
// the live error estimate work on these without OpenGL.

#include <ptview/io/Image.h>

#include <glm/glm.hpp>

namespace ptview {

// Per-pixel mean and the variance of that mean, estimated from the samples themselves.
struct PixelStatistics {
    ImageRgbF mean;
    ImageRgbF varianceOfMean;
    int sampleCount = 0;
};

// One pixel of the accumulation (Accumulator::readPixel, PathTracer::readPixel): the same numbers
// as that pixel of readStatistics, read back alone.
struct PixelReading {
    glm::vec3 mean{0.0f};           // linear radiance, the running mean
    glm::vec3 varianceOfMean{0.0f}; // the sample variance over sampleCount: standard error squared
    int sampleCount = 0;
    glm::u8vec3 displayed{0};       // as the display pass shows it (PathTracer::readPixel), sRGB 8-bit
    glm::vec3 standardError() const { return glm::sqrt(varianceOfMean); }
};

} // namespace ptview
