// Adaptive sampling on the real path tracer (renderer/tracer/AdaptiveSampler.h, docs/sampling.md):
// stopped pixels take no more samples and keep their bits; every read-back and the display divide
// each pixel by its own count; at equal samples it beats uniform sampling where the noise is
// uneven and does not lose where it is even; a threshold stops with the true error near it; and
// the image stays unbiased within its standard error.
#include <ptview/metrics/ErrorMetrics.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/tracer/AdaptiveSampler.h>
#include "GlTestContext.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

namespace ptview {
namespace {

Scene shippedScene(const char* name) { return loadScene(std::string(PTVIEW_ASSETS_DIR "/scenes/") + name + ".json"); }

RenderSettings settingsWithSeed(std::uint32_t seed) {
    RenderSettings settings;
    settings.seed = seed;
    return settings;
}

bool sameBits(glm::vec3 a, glm::vec3 b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Flags a scattered set of pixels, rows top first: about one in five.
std::vector<std::uint8_t> someStoppedPixels(glm::ivec2 size) {
    std::vector<std::uint8_t> stopped(size_t(size.x * size.y), 0);
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) stopped[size_t(y * size.x + x)] = (x * 7 + y * 3) % 5 == 0 ? 1 : 0;
    return stopped;
}

class StoppedPixels : public ::testing::TestWithParam<Backend> {};

// A pixel stopped after 16 samples keeps exactly the sums of a uniform 16-spp render, and every
// other pixel has exactly those of a uniform render of as many samples, after one more pass (32)
// and after two (48): each pixel numbers its own samples, and the mask disturbs nothing else. On
// the compute backend the passes after the stop trace only the pixels still sampled (PixelList.h)
// and write only theirs, into each of the two targets in turn. The display shows each pixel's own
// mean.
TEST_P(StoppedPixels, TakeNoFurtherSamplesAndKeepTheirBits) {
    testing::glContext();
    if (GetParam() == Backend::Compute && !PathTracer::computeSupported()) GTEST_SKIP() << "no OpenGL 4.3";
    const glm::ivec2 size(24, 18);
    auto tracerFor = [&]() {
        PathTracer tracer = makePathTracer(shippedScene("cornell_spheres"), nullptr, PathTracerOptions{false, GetParam()},
                                           settingsWithSeed(3));
        tracer.setImageSize(size);
        return tracer;
    };
    const int samplesPerPass = 16;
    PathTracer uniform = tracerFor();
    std::vector<PixelStatistics> uniformStats;
    std::vector<ImageRgba8> uniformShown;
    for (int pass = 0; pass < 3; ++pass) {
        uniform.renderSamples(samplesPerPass, samplesPerPass);
        uniformStats.push_back(uniform.readStatistics());
        uniformShown.push_back(uniform.readToneMapped(DisplaySettings{}));
    }

    PathTracer adaptive = tracerFor();
    adaptive.renderSamples(samplesPerPass, samplesPerPass);
    const std::vector<std::uint8_t> stopped = someStoppedPixels(size);
    adaptive.stopPixels(stopped);
    int stoppedCount = 0;
    for (int pass = 1; pass < 3; ++pass) {
        adaptive.renderSamples(samplesPerPass, samplesPerPass);
        const PixelStatistics stats = adaptive.readStatistics();
        const ImageRgba8 shown = adaptive.readToneMapped(DisplaySettings{});
        const int samples = (pass + 1) * samplesPerPass;
        EXPECT_EQ(stats.sampleCount, samples);
        stoppedCount = 0;
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const size_t i = size_t(y * size.x + x);
                const bool stop = stopped[i] != 0;
                stoppedCount += stop;
                const PixelStatistics& expected = uniformStats[stop ? 0 : size_t(pass)];
                EXPECT_EQ(stats.pixelSampleCounts[i], stop ? samplesPerPass : samples) << x << " " << y;
                EXPECT_EQ(stats.pixelTakesSamples[i], stop ? 0 : 1) << x << " " << y;
                EXPECT_TRUE(sameBits(stats.mean.at(x, y), expected.mean.at(x, y))) << x << " " << y << (stop ? " stopped" : "");
                EXPECT_TRUE(sameBits(stats.varianceOfMean.at(x, y), expected.varianceOfMean.at(x, y))) << x << " " << y;
                // The display divides by the pixel's own count in the shader (1 / count there, not on
                // the CPU): within one 8-bit step.
                const ImageRgba8& expectedShown = uniformShown[stop ? 0 : size_t(pass)];
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(int(shown.rgba[i * 4 + size_t(c)]), int(expectedShown.rgba[i * 4 + size_t(c)]), 1) << x << " " << y;
            }
    }
    EXPECT_GT(stoppedCount, size.x * size.y / 8);
    // A restart forgets the mask: every pixel takes samples again.
    adaptive.restart();
    adaptive.renderSamples(16);
    const PixelStatistics fresh = adaptive.readStatistics();
    for (size_t i = 0; i < fresh.pixelSampleCounts.size(); ++i) {
        EXPECT_EQ(fresh.pixelSampleCounts[i], 16);
        EXPECT_EQ(fresh.pixelTakesSamples[i], 1);
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, StoppedPixels, ::testing::Values(Backend::Fragment, Backend::Compute),
                         [](const ::testing::TestParamInfo<Backend>& info) { return std::string(backendName(info.param)); });

// The denoiser's first pass divides each pixel by its own count: under a constant sky every
// sample is the same, so with half the pixels stopped at 8 samples and the rest at 16 the
// denoised image is still that constant everywhere (dividing the stopped pixels' sums by 16 would
// halve them).
TEST(AdaptiveDenoise, TheDenoiserUsesEachPixelsOwnCount) {
    testing::glContext();
    const Scene scene = parseScene(R"({"camera": {"eye": [0, 0, 0], "target": [0, 0, -1], "vfov_deg": 40, "resolution": [16, 16]},
      "environment": {"color": [0.3, 0.5, 0.7]}, "materials": {}, "shapes": []})", "sky.json");
    PathTracer tracer = makePathTracer(scene, nullptr);
    tracer.setImageSize({16, 16});
    tracer.renderSamples(8);
    std::vector<std::uint8_t> stopped(16 * 16, 0);
    for (size_t i = 0; i < stopped.size(); i += 2) stopped[i] = 1;
    tracer.stopPixels(stopped);
    tracer.renderSamples(8);
    DenoiseSettings denoise;
    denoise.enabled = true;
    tracer.setDenoise(denoise);
    tracer.updateDenoised();
    const ImageRgbF denoised = tracer.readDenoised();
    const PixelStatistics stats = tracer.readStatistics();
    EXPECT_EQ(stats.pixelSampleCounts[0], 8);
    EXPECT_EQ(stats.pixelSampleCounts[1], 16);
    const glm::vec3 sky(0.3f, 0.5f, 0.7f);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            for (int c = 0; c < 3; ++c) {
                ASSERT_NEAR(stats.mean.at(x, y)[c], sky[c], 1e-5f) << x << " " << y;
                ASSERT_NEAR(denoised.at(x, y)[c], sky[c], 1e-5f) << x << " " << y;
            }
}

// A converged reference of the scene (another seed) and the relative MSE its own noise adds to any
// comparison with it (its variance of the mean, relative as compareToReference weighs it).
struct Reference {
    ImageRgbF mean;
    double noise = 0.0;
    double imageMean[3] = {0, 0, 0};
    double imageMeanVariance[3] = {0, 0, 0};
};

// The mean over pixels per channel and the variance of that mean (pixels independent).
void imageMean(const PixelStatistics& stats, double mean[3], double variance[3]) {
    const double pixels = double(stats.mean.width) * stats.mean.height;
    for (int c = 0; c < 3; ++c) mean[c] = variance[c] = 0.0;
    for (size_t i = 0; i < stats.mean.rgb.size(); ++i) {
        mean[i % 3] += stats.mean.rgb[i] / pixels;
        variance[i % 3] += stats.varianceOfMean.rgb[i] / (pixels * pixels);
    }
}

Reference renderReference(PathTracer& tracer, int spp) {
    RenderSettings settings = settingsWithSeed(1000);
    settings.sampler = SamplerMode::Random; // independent samples: the variance of the mean is honest
    tracer.setSettings(settings);
    tracer.restart();
    tracer.renderSamples(spp);
    PixelStatistics stats = tracer.readStatistics();
    Reference reference;
    for (size_t i = 0; i < stats.mean.rgb.size(); ++i) {
        const double r = stats.mean.rgb[i];
        reference.noise += stats.varianceOfMean.rgb[i] / (r * r + kRelativeMseEpsilon);
    }
    reference.noise /= double(stats.mean.rgb.size());
    imageMean(stats, reference.imageMean, reference.imageMeanVariance);
    reference.mean = std::move(stats.mean);
    return reference;
}

double trueRelativeMse(const ImageRgbF& image, const Reference& reference) {
    return compareToReference(image, reference.mean).relativeMse - reference.noise;
}

struct SceneCase {
    const char* name;
    double threshold;       // the noise threshold of the adaptive render
    double mostWorseShare;  // adaptive's true relMSE may be at most this times uniform's at equal samples
};

class AdaptiveOnScene : public ::testing::TestWithParam<SceneCase> {};

// Equal total samples: adaptive runs to its threshold, uniform gets its mean spp rounded up.
// Then the threshold's promise, and no bias of the image mean beyond its standard error.
TEST_P(AdaptiveOnScene, BeatsUniformAtEqualSamplesAndStopsNearItsThreshold) {
    testing::glContext();
    const SceneCase& scene = GetParam();
    PathTracer tracer = makePathTracer(shippedScene(scene.name), nullptr);
    tracer.setImageSize({32, 32});
    const Reference reference = renderReference(tracer, 4096);

    tracer.setSettings(settingsWithSeed(5));
    AdaptiveSampler adaptive(tracer, scene.threshold);
    while (!adaptive.reachedThreshold() && !adaptive.allStopped() && tracer.sampleCount() < 4096)
        adaptive.renderToNextCheck(4096);
    ASSERT_TRUE(adaptive.reachedThreshold()) << "stopped at " << tracer.sampleCount() << " spp without reaching it";
    const PixelStatistics adaptiveStats = tracer.readStatistics();
    const double adaptiveError = trueRelativeMse(adaptiveStats.mean, reference);
    const double meanSpp = adaptive.sampleCounts().mean;

    tracer.restart();
    const int uniformSpp = static_cast<int>(std::ceil(meanSpp));
    tracer.renderSamples(uniformSpp);
    const double uniformError = trueRelativeMse(tracer.readMean(), reference);
    std::printf("%s E=%g: adaptive %.1f mean spp (most %d, %.0f%% stopped): true relative error %.4f (estimated %.4f); "
                "uniform %d spp: %.4f\n",
                scene.name, scene.threshold, meanSpp, adaptive.sampleCounts().max, 100 * adaptive.sampleCounts().stoppedShare,
                relativeError(adaptiveError), relativeError(adaptive.estimate().relativeMse), uniformSpp,
                relativeError(uniformError));
    EXPECT_LT(adaptiveError, scene.mostWorseShare * uniformError);
    // The threshold's promise: the true error within 1.5x of E.
    EXPECT_LE(relativeError(adaptiveError), 1.5 * scene.threshold);
    EXPECT_GE(relativeError(adaptiveError), scene.threshold / 1.5);

    // Unbiased within its standard error (docs/sampling.md): the image mean per channel against
    // the reference's, within 4 standard errors of the difference.
    double mean[3], variance[3];
    imageMean(adaptiveStats, mean, variance);
    for (int c = 0; c < 3; ++c) {
        const double sigma = std::sqrt(variance[c] + reference.imageMeanVariance[c]);
        EXPECT_LE(std::abs(mean[c] - reference.imageMean[c]), 4.0 * sigma)
            << "channel " << c << ": " << mean[c] << " against " << reference.imageMean[c] << ", sigma " << sigma;
    }
}

// cornell_spheres: glass and a mirror sphere under a small light, noise far from even; the plain
// Cornell box is noisy almost evenly: adaptive may lose no more than noise there.
INSTANTIATE_TEST_SUITE_P(Scenes, AdaptiveOnScene,
                         ::testing::Values(SceneCase{"cornell_spheres", 0.05, 1.0}, SceneCase{"cornell", 0.05, 1.15}),
                         [](const ::testing::TestParamInfo<SceneCase>& info) { return std::string(info.param.name); });

} // namespace
} // namespace ptview
