// The noise estimate the viewer's Stats panel shows: its formula on synthetic statistics, and on
// a real render that it falls as 1/sqrt(samples), as an unbiased estimator's error does.
#include "ErrorEstimate.h"
#include "GlTestContext.h"
#include "PathTracer.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ptview {
namespace {

TEST(ErrorEstimate, IsTheRmsOfEachPixelsRelativeStandardError) {
    PixelStatistics stats;
    stats.sampleCount = 16;
    stats.mean = ImageRgbF(2, 1);
    stats.varianceOfMean = ImageRgbF(2, 1);
    stats.mean.set(0, 0, glm::vec3(1.0f));
    stats.varianceOfMean.set(0, 0, glm::vec3(0.01f)); // standard error 0.1 of a mean of 1
    stats.mean.set(1, 0, glm::vec3(4.0f));
    stats.varianceOfMean.set(1, 0, glm::vec3(0.64f)); // standard error 0.8 of a mean of 4
    double expected = std::sqrt((0.01 / (1.0 + 1e-4) + 0.64 / (16.0 + 1e-4)) / 2.0);
    ErrorEstimate estimate = estimateError(stats);
    EXPECT_NEAR(estimate.relativeError, expected, 1e-6);
    EXPECT_EQ(estimate.nonFinitePixels, 0);

    stats.mean.set(1, 0, glm::vec3(NAN, 1.0f, 1.0f));
    estimate = estimateError(stats);
    EXPECT_EQ(estimate.nonFinitePixels, 1);
    EXPECT_NEAR(estimate.relativeError, std::sqrt(0.01 / (1.0 + 1e-4)), 1e-6) << "the NaN pixel is left out";

    stats.sampleCount = 1;
    EXPECT_EQ(estimateError(stats).relativeError, 0.0) << "one sample has no variance estimate";
}

TEST(ErrorEstimate, HalvesWhenTheSamplesQuadrupleOnARealRender) {
    testing::glContext();
    PathTracer tracer;
    tracer.setScene(loadScene(PTVIEW_ASSETS_DIR "/scenes/cornell.json"));
    tracer.setImageSize({32, 32});
    RenderSettings settings;
    settings.integrator = Integrator::Full;
    settings.seed = 5;
    tracer.setSettings(settings);
    for (int i = 0; i < 16; ++i) tracer.renderSample();
    double at16 = estimateError(tracer.readStatistics()).relativeError;
    for (int i = 16; i < 64; ++i) tracer.renderSample();
    double at64 = estimateError(tracer.readStatistics()).relativeError;
    EXPECT_GT(at16, 0.0);
    // The estimate is itself noisy (1024 pixels' variances), so about a half, not exactly.
    EXPECT_NEAR(at64 / at16, 0.5, 0.1) << "at 16 spp " << at16 << ", at 64 spp " << at64;
}

} // namespace
} // namespace ptview
