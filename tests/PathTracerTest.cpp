// Behaviour of the progressive renderer on the real GLSL, headless.
#include "DisplayTransformReference.h"
#include "FoggyCornell.h"
#include "GlTestContext.h"
#include "TestFiles.h"
#include <ptview/tracer/PathTracer.h>
#include <ptview/scene/Scene.h>
#include <ptview/scene/SceneLoader.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <unistd.h>
#include <fstream>

namespace ptview {
namespace {

constexpr glm::ivec2 kSize{48, 48};

Scene cornell() {
    return loadScene(PTVIEW_ASSETS_DIR "/scenes/cornell.json");
}

ImageRgbF render(const Scene& scene, RenderSettings settings, int samplesPerPixel) {
    testing::glContext();
    PathTracer tracer;
    tracer.setScene(scene);
    tracer.setImageSize(kSize);
    tracer.setSettings(settings);
    for (int i = 0; i < samplesPerPixel; ++i) tracer.renderSample();
    return tracer.readMean();
}

TEST(PathTracer, DepthZeroShowsOnlyEmittersSeenDirectly) {
    ImageRgbF image = render(cornell(), testing::naiveSettings(0, 3), 4);
    int lit = 0;
    for (int y = 0; y < kSize.y; ++y) {
        for (int x = 0; x < kSize.x; ++x) {
            glm::vec3 value = image.at(x, y);
            if (value == glm::vec3(0.0f)) continue;
            ++lit;
            // Only the light (17, 12, 4), partly covering edge pixels.
            EXPECT_NEAR(value.g / value.r, 12.0f / 17.0f, 1e-4f);
            EXPECT_LE(value.r, 17.0f + 1e-4f);
            EXPECT_LT(y, kSize.y / 4) << "the light is at the top of the image";
        }
    }
    EXPECT_GT(lit, 5);
    EXPECT_LT(lit, kSize.x * kSize.y / 20);
}

TEST(PathTracer, EachExtraBounceOnlyAddsLight) {
    // The same seed replays the same path prefixes, so deeper renders add light pixel by pixel.
    Scene scene = cornell();
    ImageRgbF previous = render(scene, testing::naiveSettings(1, 5), 2);
    for (int depth = 2; depth <= 4; ++depth) {
        ImageRgbF deeper = render(scene, testing::naiveSettings(depth, 5), 2);
        double added = 0.0;
        for (int y = 0; y < kSize.y; ++y)
            for (int x = 0; x < kSize.x; ++x) {
                glm::vec3 gain = deeper.at(x, y) - previous.at(x, y);
                EXPECT_GE(glm::min(gain.r, glm::min(gain.g, gain.b)), -1e-4f * (1.0f + deeper.at(x, y).r));
                added += gain.r + gain.g + gain.b;
            }
        EXPECT_GT(added, 0.0) << "depth " << depth << " should add indirect light";
        previous = deeper;
    }
}

TEST(PathTracer, SeedReproducesOrDecorrelates) {
    Scene scene = cornell();
    ImageRgbF a = render(scene, testing::naiveSettings(4, 11), 2);
    ImageRgbF b = render(scene, testing::naiveSettings(4, 11), 2);
    ImageRgbF c = render(scene, testing::naiveSettings(4, 12), 2);
    EXPECT_EQ(a.rgb, b.rgb);
    EXPECT_NE(a.rgb, c.rgb);
}

TEST(PathTracer, MirrorAndGlassSpheresRenderFinitePlausibleImages) {
    Scene spheres = loadScene(PTVIEW_ASSETS_DIR "/scenes/cornell_spheres.json");
    ImageRgbF image = render(spheres, testing::naiveSettings(16, 9), 16);
    glm::dvec3 sum(0.0);
    for (float value : image.rgb) ASSERT_TRUE(std::isfinite(value));
    for (int y = 0; y < kSize.y; ++y)
        for (int x = 0; x < kSize.x; ++x) sum += glm::dvec3(image.at(x, y));
    glm::dvec3 mean = sum / double(kSize.x * kSize.y);
    // The plain box's mean is (0.215, 0.142, 0.041); lossless spheres change it by some percent.
    EXPECT_NEAR(mean.r, 0.215, 0.05);
    EXPECT_NEAR(mean.g, 0.142, 0.035);
    EXPECT_NEAR(mean.b, 0.041, 0.012);
}

TEST(PathTracer, EveryShippedSceneLoadsAndRendersFinitePixels) {
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(PTVIEW_ASSETS_DIR "/scenes")) {
        if (entry.path().extension() != ".json") continue;
        ++scenes;
        Scene scene = loadScene(entry.path());
        ImageRgbF image = render(scene, testing::naiveSettings(8, 4), 4);
        double sum = 0.0;
        for (float value : image.rgb) {
            ASSERT_TRUE(std::isfinite(value)) << entry.path();
            sum += value;
        }
        EXPECT_GT(sum, 0.0) << entry.path() << " renders black";
    }
    EXPECT_GE(scenes, 3);
}

TEST(PathTracer, ChangingSettingsOrSizeRestartsAccumulation) {
    testing::glContext();
    PathTracer tracer;
    tracer.setScene(cornell());
    tracer.setImageSize(kSize);
    for (int i = 0; i < 3; ++i) tracer.renderSample();
    EXPECT_EQ(tracer.sampleCount(), 3);
    tracer.setSettings(tracer.settings()); // no change: keep going
    tracer.setImageSize(kSize);
    EXPECT_EQ(tracer.sampleCount(), 3);
    RenderSettings deeper = tracer.settings();
    deeper.maxDepth += 1;
    tracer.setSettings(deeper);
    EXPECT_EQ(tracer.sampleCount(), 0);
    tracer.renderSample();
    tracer.setImageSize({kSize.x + 1, kSize.y});
    EXPECT_EQ(tracer.sampleCount(), 0);
    EXPECT_THROW(tracer.setImageSize({0, 10}), std::invalid_argument);
    EXPECT_THROW(tracer.setImageSize({1 << 20, 10}), std::invalid_argument);
}

// The viewer spreads a sample over several frames in row tiles; the sums must be exactly those of
// whole passes, and the new sample must only show once its last row is done.
TEST(PathTracer, RowTilesAccumulateExactlyLikeWholePasses) {
    testing::glContext();
    Scene scene = cornell();
    RenderSettings settings = testing::naiveSettings(4, 11);
    settings.sampler = SamplerMode::Sobol;
    PathTracer whole, tiled;
    for (PathTracer* tracer : {&whole, &tiled}) {
        tracer->setScene(scene);
        tracer->setImageSize(kSize);
        tracer->setSettings(settings);
    }
    for (int i = 0; i < 3; ++i) whole.renderSample();
    int passes = 0;
    while (passes < 3) {
        int before = tiled.sampleCount();
        bool done = tiled.renderRows(7); // 48 rows: 6 full tiles and one of 6
        EXPECT_EQ(tiled.sampleCount(), before + (done ? 1 : 0));
        passes += done ? 1 : 0;
    }
    EXPECT_EQ(tiled.nextRow(), 0);
    ImageRgbF a = whole.readMean(), b = tiled.readMean();
    ASSERT_EQ(a.rgb.size(), b.rgb.size());
    for (size_t i = 0; i < a.rgb.size(); ++i) ASSERT_EQ(a.rgb[i], b.rgb[i]) << "at float " << i;
}

// renderSamples traces a pass's samples in one loop, starting a pixel's next path as soon as its
// last one ends (pathtrace_sample.glsl). Those are the samples single passes trace, so the means
// and second moments agree to float rounding (each pass's samples are summed before the Kahan
// add); a reused or skipped sample index would be a difference of the size of the noise. That
// holds across the light's outline too, where a sample is its path and its edge rays
// (emission_edges.glsl), squared together: pairing a pass's paths and edge rays as a whole, as
// ptview once did, fails there. The outline's pixels are those whose camera rays see the light in
// some samples and not in others (a depth-0 image's noise), and the pixels beside them.
std::vector<bool> nearEmissionEdges(const Scene& scene, glm::ivec2 size) {
    RenderSettings settings;
    settings.maxDepth = 0;
    settings.sampler = SamplerMode::Random;
    PathTracer tracer;
    tracer.setScene(scene);
    tracer.setImageSize(size);
    tracer.setSettings(settings);
    tracer.renderSamples(64);
    PixelStatistics emission = tracer.readStatistics();
    std::vector<bool> near(static_cast<size_t>(size.x * size.y), false);
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            if (emission.varianceOfMean.at(x, y).r == 0.0f) continue;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    if (x + dx >= 0 && x + dx < size.x && y + dy >= 0 && y + dy < size.y)
                        near[static_cast<size_t>((y + dy) * size.x + x + dx)] = true;
        }
    return near;
}

TEST(PathTracer, SeveralSamplesPerPassAreTheSamplesOfSinglePasses) {
    testing::glContext();
    Scene scene = loadScene(PTVIEW_ASSETS_DIR "/scenes/cornell_spheres.json");
    const std::vector<bool> nearEdges = nearEmissionEdges(scene, kSize);
    const auto edgePixels = std::count(nearEdges.begin(), nearEdges.end(), true);
    EXPECT_GT(edgePixels, 0) << "the light's outline is in view";
    EXPECT_LT(edgePixels, kSize.x * kSize.y / 10) << "and the rest of the image is most of it";
    constexpr int kSamples = 20; // at 48x48, a pass of 16 and one of 4
    struct Case { Integrator integrator; SamplerMode sampler; DebugView view; };
    for (Case c : {Case{Integrator::Naive, SamplerMode::Random, DebugView::Radiance},
                   Case{Integrator::Direct, SamplerMode::Sobol, DebugView::Radiance},
                   Case{Integrator::Mis, SamplerMode::Random, DebugView::Radiance},
                   Case{Integrator::Full, SamplerMode::Sobol, DebugView::Radiance},
                   Case{Integrator::Full, SamplerMode::Random, DebugView::Normals}}) {
        RenderSettings settings;
        settings.integrator = c.integrator;
        settings.sampler = c.sampler;
        settings.debugView = c.view;
        settings.maxDepth = 16;
        settings.seed = 7;
        PathTracer single, batched;
        for (PathTracer* tracer : {&single, &batched}) {
            tracer->setScene(scene);
            tracer->setImageSize(kSize);
            tracer->setSettings(settings);
        }
        ASSERT_EQ(batched.samplesPerPass(), 16);
        for (int i = 0; i < kSamples; ++i) single.renderSample();
        batched.renderSamples(kSamples);
        ASSERT_EQ(batched.sampleCount(), kSamples);
        PixelStatistics a = single.readStatistics(), b = batched.readStatistics();
        ASSERT_EQ(a.mean.rgb.size(), b.mean.rgb.size());
        double spread = 0.0; // the noise a wrong sample would show: mean standard error
        for (size_t i = 0; i < a.mean.rgb.size(); ++i) {
            const float x = a.mean.rgb[i], y = b.mean.rgb[i];
            ASSERT_NEAR(x, y, 1e-5f * std::max(1.0f, std::abs(x))) << "at float " << i << ", integrator " << int(c.integrator);
            const float vx = a.varianceOfMean.rgb[i], vy = b.varianceOfMean.rgb[i];
            ASSERT_NEAR(vx, vy, 1e-4f * std::max(1e-3f, std::abs(vx)))
                << "at float " << i << (nearEdges[i / 3] ? ", by the light's outline" : "");
            spread += std::sqrt(vx);
        }
        EXPECT_GT(spread / a.mean.rgb.size(), 1e-3) << "the image has noise a wrong sample would change";
    }
}

TEST(PathTracer, RestartMidPassStartsTheNextPassAtRowZero) {
    testing::glContext();
    PathTracer tracer;
    tracer.setScene(cornell());
    tracer.setImageSize(kSize);
    tracer.renderSample();
    EXPECT_FALSE(tracer.renderRows(10));
    EXPECT_EQ(tracer.nextRow(), 10);
    int restarts = tracer.restartCount();
    tracer.setCamera(cornell().camera);
    EXPECT_EQ(tracer.restartCount(), restarts + 1);
    EXPECT_EQ(tracer.nextRow(), 0);
    EXPECT_EQ(tracer.sampleCount(), 0);
    EXPECT_TRUE(tracer.renderRows(kSize.y));
    EXPECT_EQ(tracer.sampleCount(), 1);
}

// A constant environment seen directly (depth 0): every pixel's mean is that radiance, so each
// tone mapper's output is known in closed form.
TEST(PathTracer, ToneMappersMatchTheirFormulas) {
    testing::glContext();
    Scene scene;
    scene.camera.resolution = {8, 8};
    scene.environment = glm::vec3(0.25f, 1.0f, 4.0f);
    PathTracer tracer;
    tracer.setScene(scene);
    tracer.setImageSize({8, 8});
    tracer.setSettings(testing::naiveSettings(0, 1));
    tracer.renderSample();
    auto encode = [](double linear) { return testing::srgbEncode(linear) * 255.0; };
    auto reinhard = [](double x) { return x / (1.0 + x); };
    auto aces = [](double x) { return (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14); };
    const float exposureStops = 1.0f; // doubles the radiance first
    const glm::dvec3 agx = testing::agx(2.0 * glm::dvec3(scene.environment));
    for (const EnumEntry<ToneMapper>& entry : toneMapperNames()) {
        ImageRgba8 image = tracer.readToneMapped(DisplaySettings{exposureStops, entry.value});
        for (int c = 0; c < 3; ++c) {
            double x = 2.0 * scene.environment[c];
            double expected = entry.value == ToneMapper::Reinhard ? encode(reinhard(x))
                            : entry.value == ToneMapper::Aces     ? encode(aces(x))
                            : entry.value == ToneMapper::Agx      ? encode(agx[c])
                            // Without an OpenColorIO view (OcioViewTest has them) the values are only clamped.
                            : entry.value == ToneMapper::Ocio     ? 255.0 * std::min(x, 1.0)
                                                                  : encode(x);
            EXPECT_NEAR(image.rgba[static_cast<size_t>(c)], expected, 1.0) << entry.name << " channel " << c;
        }
    }
    // Images whose provenance predates the sRGB curve are encoded with gamma 2.2 again.
    DisplaySettings old{exposureStops, ToneMapper::Reinhard};
    old.transfer = DisplayTransfer::Gamma22;
    ImageRgba8 image = tracer.readToneMapped(old);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(image.rgba[static_cast<size_t>(c)], 255.0 * testing::gamma22Encode(reinhard(2.0 * scene.environment[c])), 1.0);
}

// The PNG (readToneMapped), the window and the pixel inspector (readDisplayed, the magnifier and
// the "displayed" numbers) all come from the one display pass, so a pixel reads the same in each.
TEST(PathTracer, SavedImageAndDisplayedPixelsAgree) {
    testing::glContext();
    Scene scene;
    scene.camera.resolution = {8, 8};
    scene.environment = glm::vec3(0.002f, 0.3f, 2.0f); // one channel on sRGB's linear segment
    PathTracer tracer;
    tracer.setScene(scene);
    tracer.setImageSize({8, 8});
    tracer.setSettings(testing::naiveSettings(0, 1));
    tracer.renderSample();
    for (ToneMapper toneMapper : {ToneMapper::Reinhard, ToneMapper::Agx}) {
        const DisplaySettings display{0.0f, toneMapper};
        ImageRgba8 saved = tracer.readToneMapped(display);
        ImageRgba8 shown = tracer.readDisplayed({3, 4}, {1, 1}, display);
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(shown.rgba[static_cast<size_t>(c)], saved.rgba[static_cast<size_t>((4 * 8 + 3) * 4 + c)]) << c;
        }
        const double linear = toneMapper == ToneMapper::Agx ? testing::agx(glm::dvec3(scene.environment)).x
                                                            : 0.002 / 1.002;
        EXPECT_NEAR(saved.rgba[0], 255.0 * testing::srgbEncode(linear), 1.0) << toneMapperName(toneMapper);
    }
}

// The debug views show the first surface's data: its normal and its albedo, exactly.
TEST(PathTracer, DebugViewsShowNormalsAndAlbedo) {
    testing::glContext();
    PathTracer tracer;
    tracer.setScene(cornell());
    tracer.setImageSize(kSize);
    RenderSettings settings = testing::naiveSettings(4, 3);
    settings.debugView = DebugView::Albedo;
    tracer.setSettings(settings);
    for (int i = 0; i < 2; ++i) tracer.renderSample();
    ImageRgbF albedo = tracer.readMean();
    // Well inside the left (red) wall and the floor near it (rows run top-down), every sample sees
    // the same surface.
    EXPECT_NEAR(glm::distance(albedo.at(2, kSize.y / 2), glm::vec3(0.63f, 0.065f, 0.05f)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::distance(albedo.at(kSize.x / 5, 40), glm::vec3(0.73f)), 0.0f, 1e-5f);
    settings.debugView = DebugView::Normals;
    tracer.setSettings(settings);
    EXPECT_EQ(tracer.sampleCount(), 0) << "changing the view restarts accumulation";
    for (int i = 0; i < 2; ++i) tracer.renderSample();
    ImageRgbF normals = tracer.readMean();
    EXPECT_NEAR(glm::distance(normals.at(kSize.x / 5, 40), glm::vec3(0.5f, 1.0f, 0.5f)), 0.0f, 1e-5f) << "the floor faces +Y";
    EXPECT_NEAR(glm::distance(normals.at(2, kSize.y / 2), glm::vec3(1.0f, 0.5f, 0.5f)), 0.0f, 1e-5f) << "the left wall faces +X";
}

// A fog box is no surface: the debug views of the foggy Cornell box are those of the clear one,
// normals and albedo exactly (the same surfaces), depth to a few 1e-3 m. Past each face of the fog
// the ray goes on from a point spawnRay moved off the face along its normal, a sideways shift of up
// to a few 1e-3 at a grazing crossing, so a ray that close to an edge of the box may meet the other
// surface: a few pixels on the edges may differ. Were the fog's faces shown, almost none would agree.
TEST(PathTracer, DebugViewsSeeThroughAFogBox) {
    testing::glContext();
    const Scene clear = cornell(), foggy = parseScene(testing::foggyCornellJson(), testing::kFoggyCornellName);
    for (DebugView view : {DebugView::Normals, DebugView::Albedo, DebugView::Depth}) {
        ImageRgbF images[2];
        for (int i = 0; i < 2; ++i) {
            PathTracer tracer;
            tracer.setScene(i == 0 ? clear : foggy);
            tracer.setImageSize(kSize);
            RenderSettings settings = testing::naiveSettings(4, 3);
            settings.debugView = view;
            tracer.setSettings(settings);
            for (int sample = 0; sample < 2; ++sample) tracer.renderSample();
            images[i] = tracer.readMean();
        }
        const float tolerance = view == DebugView::Depth ? 5e-3f : 0.0f;
        int differing = 0;
        double total = 0.0;
        for (int y = 0; y < kSize.y; ++y)
            for (int x = 0; x < kSize.x; ++x) {
                const glm::vec3 a = images[0].at(x, y), b = images[1].at(x, y);
                differing += glm::any(glm::greaterThan(glm::abs(a - b), glm::vec3(tolerance)));
                total += a.x + a.y + a.z;
            }
        EXPECT_LE(differing, kSize.x * kSize.y / 100) << debugViewName(view);
        EXPECT_GT(total, 0.0) << "a black image would agree with anything";
    }
}

// The NaN/Inf debug view marks non-finite pixels magenta. A copy of the shaders whose sample is
// NaN on the left half and infinite on the top rows stands in for a bug.
TEST(PathTracer, NonFinitePixelsAreHighlightedInMagenta) {
    testing::glContext();
    testing::ScratchFiles scratch("nan_shaders");
    const std::filesystem::path shaders = scratch.directory() / "shaders";
    std::filesystem::copy(PTVIEW_SHADER_DIR, shaders, std::filesystem::copy_options::recursive);
    std::ofstream(shaders / "pathtrace_sample.glsl") << R"(#include "frame_uniforms.glsl"
#include "specialization.glsl"
uniform float uZero; // 0, but unknown to the compiler
void traceSamples(uvec2 pixel) {
    float nan = uZero / uZero;
    float inf = 1.0 / uZero;
    vec3 value = pixel.x < uImageSize.x / 2 ? vec3(nan) : pixel.y >= uImageSize.y - 2 ? vec3(inf) : vec3(0.25);
    accumulateSamples(ivec2(pixel), value, value * value, 1u, 0u);
}
)";
    PathTracer tracer(shaders);
    tracer.setScene(cornell());
    tracer.setImageSize({8, 8});
    tracer.renderSample();
    DisplaySettings display;
    display.highlightNonFinite = true;
    ImageRgba8 shown = tracer.readToneMapped(display);
    auto pixel = [&](int x, int y) {
        const std::uint8_t* p = &shown.rgba[static_cast<size_t>((y * 8 + x) * 4)];
        return glm::ivec3(p[0], p[1], p[2]);
    };
    EXPECT_EQ(pixel(1, 4), glm::ivec3(255, 0, 255)) << "NaN";
    EXPECT_EQ(pixel(6, 0), glm::ivec3(255, 0, 255)) << "infinite (the top rows: readback rows run top-down)";
    glm::ivec3 finite = pixel(6, 4);
    EXPECT_NE(finite, glm::ivec3(255, 0, 255));
    EXPECT_EQ(finite.r, finite.g);
}

// The viewer's preview: levels at 1/8 of the width (and coarser while they keep ~256 pixels or
// more), four samples each, shown only until the full size has a sample, and never read back.
TEST(PathTracer, PreviewIsShownUntilTheFirstFullSampleAndNeverReadBack) {
    testing::glContext();
    PathTracer tracer;
    tracer.setScene(cornell());
    RenderSettings settings;
    settings.maxDepth = 0; // the light alone: cheap, and bright where it is seen
    tracer.setSettings(settings);
    const glm::ivec2 size{400, 330}; // just over the 2^17 pixels below which there is no preview
    tracer.setImageSize(size);
    EXPECT_FALSE(tracer.previewWanted()) << "off by default: the headless renderer has no use for it";
    tracer.setPreviewEnabled(true);
    ASSERT_TRUE(tracer.previewWanted());
    EXPECT_EQ(tracer.shownPreviewSize(), glm::ivec2(0));
    int passes = 0;
    while (tracer.previewWanted() && passes < 100) passes += tracer.renderPreviewRows(1000);
    EXPECT_EQ(passes, PathTracer::kPreviewSamples) << "one level (1/32 would have 143 pixels), four samples";
    EXPECT_EQ(tracer.shownPreviewSize(), glm::ivec2(50, 42)); // 400/8, 330/8 rounded up
    EXPECT_EQ(tracer.sampleCount(), 0);

    // The read-back is the full-size accumulation, which has nothing yet: black, not the preview.
    auto litPixels = [](const ImageRgba8& image) {
        int lit = 0;
        for (size_t i = 0; i < image.rgba.size(); i += 4) lit += image.rgba[i] > 128;
        return lit;
    };
    ImageRgba8 beforeSample = tracer.readToneMapped(DisplaySettings{});
    EXPECT_EQ(beforeSample.width, size.x);
    EXPECT_EQ(litPixels(beforeSample), 0);

    tracer.renderSample();
    EXPECT_EQ(tracer.shownPreviewSize(), glm::ivec2(0)) << "the full size replaces the preview";
    EXPECT_FALSE(tracer.previewWanted());
    EXPECT_GT(litPixels(tracer.readToneMapped(DisplaySettings{})), 200) << "the light, seen directly";

    tracer.restart(); // a camera move: the preview starts over with the render
    EXPECT_TRUE(tracer.previewWanted());
}

} // namespace
} // namespace ptview
