// Long accumulations keep their mean: 1e5 frames through the real accumulate.glsl.
#include <ptview/tracer/Accumulator.h>
#include <ptview/gl/GlProgram.h>
#include "GlTestContext.h"
#include <ptview/gpudata/GpuLayout.h>
#include <ptview/gl/ShaderAssembler.h>

#include <gtest/gtest.h>

#include <cmath>

namespace ptview {
namespace {

float probeValue(std::uint32_t frame) { // mirrors tests/shaders/accumulate_probe.frag
    std::uint32_t k = frame % 10u;
    return k == 9u ? 10000.0f : 0.125f * static_cast<float>(k) + 0.0625f;
}

// Runs `frames` probe passes into accumulator after `framesBeforeRestart` passes that a restart
// must discard.
void accumulateProbe(Accumulator& accumulator, int frames, int framesBeforeRestart = 0) {
    ShaderAssembler assembler(PTVIEW_SHADER_DIR);
    GlProgram program(assembler.assemble("fullscreen.vert"),
                      assembler.assemble(PTVIEW_TEST_SHADER_DIR "/accumulate_probe.frag"));
    program.bindUniformBlock("FrameBlock", 0);
    Accumulator::bindSamplers(program, 0);

    GlBuffer frameBuffer = createBuffer();
    glBindBuffer(GL_UNIFORM_BUFFER, frameBuffer.id());
    glBufferData(GL_UNIFORM_BUFFER, sizeof(FrameUniforms), nullptr, GL_DYNAMIC_DRAW);
    GlVertexArray vertexArray = createVertexArray();

    FrameUniforms frame{};
    for (int i = 0; i < framesBeforeRestart + frames; ++i) {
        if (i == framesBeforeRestart) accumulator.restart();
        frame.frameIndex = static_cast<std::uint32_t>(accumulator.sampleCount());
        glBindBuffer(GL_UNIFORM_BUFFER, frameBuffer.id());
        glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof(FrameUniforms), &frame);
        accumulator.beginPass(0);
        glUseProgram(program.id());
        glBindBufferBase(GL_UNIFORM_BUFFER, 0, frameBuffer.id());
        glBindVertexArray(vertexArray.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        accumulator.endPass(1);
    }
}

PixelStatistics runProbe(int frames, glm::ivec2 size, int framesBeforeRestart = 0) {
    testing::glContext();
    Accumulator accumulator;
    accumulator.resize(size);
    accumulateProbe(accumulator, frames, framesBeforeRestart);
    return accumulator.readStatistics();
}

// The pixel inspector's one-pixel read: the mean and the variance of the mean (the standard
// error squared) of the known sequence, by the formula on its exact sums, s^2 / n with the
// unbiased sample variance s^2 = (sum x^2 - n mean^2) / (n - 1).
TEST(Accumulator, ReadPixelGivesTheMeanAndStandardErrorOfTheSamples) {
    testing::glContext();
    const int frames = 23; // two large values among them: a variance far from zero
    double sum = 0.0, sumSquares = 0.0;
    for (int i = 0; i < frames; ++i) {
        double v = probeValue(static_cast<std::uint32_t>(i));
        sum += v;
        sumSquares += v * v;
    }
    const double mean = sum / frames;
    const double varianceOfMean = (sumSquares - frames * mean * mean) / (frames - 1) / frames;
    Accumulator accumulator;
    accumulator.resize({5, 3});
    accumulateProbe(accumulator, frames);
    PixelReading reading = accumulator.readPixel({4, 1});
    EXPECT_EQ(reading.sampleCount, frames);
    EXPECT_NEAR(reading.mean.r, mean, 1e-6 * mean);
    EXPECT_NEAR(reading.mean.g, 0.5 * mean, 1e-6 * mean);
    EXPECT_NEAR(reading.varianceOfMean.r, varianceOfMean, 1e-5 * varianceOfMean);
    EXPECT_NEAR(reading.varianceOfMean.g, 0.25 * varianceOfMean, 1e-5 * varianceOfMean);
    EXPECT_NEAR(reading.standardError().r, std::sqrt(varianceOfMean), 1e-5 * std::sqrt(varianceOfMean));
    EXPECT_THROW(accumulator.readPixel({5, 0}), std::out_of_range);
}

TEST(Accumulator, HundredThousandFramesKeepTheExactMean) {
    const int frames = 100000;
    double exactSum = 0.0, exactSumSquares = 0.0;
    float naiveFloatSum = 0.0f;
    for (int i = 0; i < frames; ++i) {
        double v = probeValue(static_cast<std::uint32_t>(i));
        exactSum += v;
        exactSumSquares += v * v;
        naiveFloatSum += probeValue(static_cast<std::uint32_t>(i));
    }
    const double exactMean = exactSum / frames;
    // The test is only meaningful if a plain float sum would fail it.
    ASSERT_GT(std::abs(naiveFloatSum / frames - exactMean) / exactMean, 1e-4);

    PixelStatistics stats = runProbe(frames, {4, 4});
    ASSERT_EQ(stats.sampleCount, frames);
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 4; ++x) {
            glm::vec3 mean = stats.mean.at(x, y);
            EXPECT_NEAR(mean.r, exactMean, 1e-5 * exactMean);
            EXPECT_NEAR(mean.g, 0.5 * exactMean, 1e-5 * 0.5 * exactMean);
            EXPECT_NEAR(mean.b, exactMean + 1.0, 1e-5 * (exactMean + 1.0));
        }
    }
    // The second moment is a plain float sum: good to a few 1e-4, enough for error bars.
    double exactVarianceOfMean = (exactSumSquares / frames - exactMean * exactMean) * frames / (frames - 1) / frames;
    EXPECT_NEAR(stats.varianceOfMean.at(0, 0).r, exactVarianceOfMean, 1e-2 * exactVarianceOfMean);
}

TEST(Accumulator, RestartDiscardsEarlierSamples) {
    PixelStatistics stats = runProbe(10, {3, 2}, 7);
    // One full cycle of the probe sequence: (0.0625 + ... + 1.0625) + 1000, over 10.
    double expected = (9 * 0.0625 + 0.125 * 36 + 10000.0) / 10.0;
    EXPECT_EQ(stats.sampleCount, 10);
    EXPECT_NEAR(stats.mean.at(2, 1).r, expected, 1e-6 * expected);
    EXPECT_EQ(stats.mean.width, 3);
    EXPECT_EQ(stats.mean.height, 2);
}

} // namespace
} // namespace ptview
