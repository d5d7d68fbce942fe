#pragma once
// What the accumulation knows about each pixel, read back as plain images: the error metrics and
// the live error estimate work on these without OpenGL.

#include <ptview/io/Image.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace ptview {

// Per-pixel mean and the variance of that mean, estimated from the samples themselves.
struct PixelStatistics {
    ImageRgbF mean;
    ImageRgbF varianceOfMean;
    int sampleCount = 0; // the most any pixel has: every pixel's unless adaptive sampling stopped some
    // Each pixel's own count, rows top first (adaptive sampling stops pixels early; docs/sampling.md).
    std::vector<int> pixelSampleCounts;
    // Each pixel's flag "still takes samples" (1) or "stopped by adaptive sampling" (0), rows top first.
    std::vector<std::uint8_t> pixelTakesSamples;
};

// One pixel of the accumulation (Accumulator::readPixel, PathTracer::readPixel): the same numbers
// as that pixel of readStatistics, read back alone.
struct PixelReading {
    glm::vec3 mean{0.0f};           // linear radiance, the running mean
    glm::vec3 varianceOfMean{0.0f}; // the sample variance over sampleCount: standard error squared
    int sampleCount = 0;            // the pixel's own
    glm::u8vec3 displayed{0};       // as the display pass shows it (PathTracer::readPixel), sRGB 8-bit
    glm::vec3 standardError() const { return glm::sqrt(varianceOfMean); }
};

} // namespace ptview
