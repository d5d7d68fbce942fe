#pragma once
// Progressive accumulation targets: per pixel, a Kahan-compensated sum of samples and a sum of
// squares, in RGBA32F textures that are ping-ponged (a pass reads the previous sums and writes
// the new ones). shaders/accumulate.glsl is the GPU half.

#include <ptview/gl/GlObjects.h>
#include <ptview/gl/GlProgram.h>
#include <ptview/io/Image.h>
#include <ptview/metrics/PixelStatistics.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace ptview {

class Accumulator {
public:
    static constexpr int kTextureCount = 3; // sum, compensation, sum of squares

    // Points a program's accumulate.glsl samplers at units firstUnit .. firstUnit + 2.
    static void bindSamplers(const GlProgram& program, int firstUnit);

    // Reallocates (and restarts) only when the size changes. Throws std::invalid_argument for
    // sizes the GPU cannot hold.
    void resize(glm::ivec2 size);
    // The next pass starts a new sum. Until it completes, displayedSampleCount() keeps describing
    // the previous sums, so a viewer can keep showing the old image rather than black.
    void restart() {
        if (sampleCount_ > 0) staleSampleCount_ = sampleCount_;
        sampleCount_ = 0;
        hasStoppedPixels_ = false;
    }

    // Points a compute program's accumulate_image.glsl images at image units firstImageUnit .. + 2.
    static void bindImages(const GlProgram& program, int firstImageUnit);

    // Binds the target to draw into and the previous sums for reading; the caller then draws
    // samples per pixel with a program that calls accumulateSamples(), then ends the pass with
    // how many it added.
    void beginPass(int firstUnit) const;
    // The same for a compute dispatch: the target's textures become images to store into.
    void beginComputePass(int firstUnit, int firstImageUnit) const;
    void endPass(int samplesAdded);

    // Binds the latest sum and compensation for display.
    void bindLatest(int sumUnit, int compensationUnit) const;
    // And the sum of squares (the denoiser's variance).
    void bindLatest(int sumUnit, int compensationUnit, int sumSquaresUnit) const;

    // Adaptive sampling: the pixels flagged (rows top first, size().x * size().y of them) take no
    // more samples until the next restart; the others go on. Writes the flag into the latest sum
    // of squares' alpha (accumulate_sum.glsl), rewriting its colour channels bit for bit. Returns
    // every pixel stopped since the restart, these and earlier ones, flagged the same way (empty
    // before the first pass, which starts afresh).
    std::vector<std::uint8_t> stopPixels(const std::vector<std::uint8_t>& stopped);
    // Copies the latest sums into the target the next pass writes (OpenGL 4.3), so that a pass
    // that writes only some pixels (PixelList.h) leaves the others as they are.
    void copyLatestIntoNext() const;
    // Whether stopPixels stopped any pixel since the last restart: the display then divides each
    // pixel by its own count.
    bool hasStoppedPixels() const { return hasStoppedPixels_ && sampleCount_ > 0; }

    PixelStatistics readStatistics() const;
    // One pixel of readStatistics (glPixel counts rows from the bottom, as GL does), read back
    // alone: three 1x1 reads instead of the whole image. `displayed` is left 0.
    PixelReading readPixel(glm::ivec2 glPixel) const;

    int sampleCount() const { return sampleCount_; }
    // The sample count of the sums bindLatest() binds: sampleCount(), or right after a restart
    // the count of the sums still there (0 after a resize).
    int displayedSampleCount() const { return sampleCount_ > 0 ? sampleCount_ : staleSampleCount_; }
    glm::ivec2 size() const { return size_; }

private:
    struct Target {
        GlFramebuffer framebuffer;
        GlTexture textures[kTextureCount];
    };
    const Target& latest() const { return targets_[1 - writeIndex_]; }
    void readAttachment(int attachment, std::vector<float>& rgba) const;

    Target targets_[2];
    int writeIndex_ = 0;
    int sampleCount_ = 0;
    int staleSampleCount_ = 0;
    bool hasStoppedPixels_ = false;
    glm::ivec2 size_{0, 0};
};

} // namespace ptview
