// The light-path explorer (renderer/settings/LightPaths.h) on the real GLSL: its views split the
// image into parts that add up to it, sample for sample (the paths traced are the same, only
// what is added changes), caustics need mirrors or glass, a medium's scattering is a bounce, and a
// program that shows all the light carries none of the explorer's code.
#include "FoggyCornell.h"
#include "GlTestContext.h"
#include <ptview/tracer/PathTracer.h>
#include <ptview/scene/SceneLoader.h>

#include <gtest/gtest.h>

#include <cmath>

namespace ptview {
namespace {

constexpr glm::ivec2 kSize{32, 32};
constexpr int kSpp = 4;

Scene scene(const char* name) {
    if (std::string(name) == "foggy_cornell") return parseScene(testing::foggyCornellJson(), testing::kFoggyCornellName);
    return loadScene(std::string(PTVIEW_ASSETS_DIR "/scenes/") + name + ".json");
}

RenderSettings settingsFor(Integrator integrator, LightPaths paths, int bounces = 1) {
    RenderSettings settings;
    settings.integrator = integrator;
    settings.sampler = SamplerMode::Random;
    settings.seed = 11;
    settings.maxDepth = 4;
    settings.lightPaths = paths;
    settings.lightPathBounces = bounces;
    return settings;
}

ImageRgbF render(const Scene& scene, const RenderSettings& settings, int spp = kSpp) {
    testing::glContext();
    PathTracer tracer;
    tracer.setScene(scene);
    tracer.setImageSize(kSize);
    tracer.setSettings(settings);
    for (int i = 0; i < spp; ++i) tracer.renderSample();
    return tracer.readMean();
}

// The parts and the whole agree per pixel and channel up to float rounding of the sums.
void expectSameImage(const ImageRgbF& sum, const ImageRgbF& whole, const std::string& what) {
    ASSERT_EQ(sum.rgb.size(), whole.rgb.size());
    double wholeTotal = 0.0;
    for (std::size_t i = 0; i < whole.rgb.size(); ++i) {
        wholeTotal += whole.rgb[i];
        ASSERT_NEAR(sum.rgb[i], whole.rgb[i], 1e-4f * (1.0f + std::abs(whole.rgb[i]))) << what << " at float " << i;
    }
    EXPECT_GT(wholeTotal, 0.0) << "a black image would agree with anything";
}

void add(ImageRgbF& sum, const ImageRgbF& part) {
    for (std::size_t i = 0; i < sum.rgb.size(); ++i) sum.rgb[i] += part.rgb[i];
}

double total(const ImageRgbF& image) {
    double sum = 0.0;
    for (float v : image.rgb) sum += v;
    return sum;
}

struct Case {
    const char* scene;
    Integrator integrator;
};

class LightPathViews : public ::testing::TestWithParam<Case> {};

TEST_P(LightPathViews, ExactlyKImagesSumToTheFullImage) {
    const Scene s = scene(GetParam().scene);
    const ImageRgbF all = render(s, settingsFor(GetParam().integrator, LightPaths::All));
    ImageRgbF sum(kSize.x, kSize.y);
    for (int k = 0; k <= 4; ++k) {
        ImageRgbF part = render(s, settingsFor(GetParam().integrator, LightPaths::Exactly, k));
        // With the full integrator every bounce up to the depth carries light here.
        if (GetParam().integrator == Integrator::Full) {
            EXPECT_GT(total(part), 0.0) << "k = " << k;
        }
        add(sum, part);
    }
    expectSameImage(sum, all, "sum of exactly-k over k = 0..4");
    EXPECT_EQ(total(render(s, settingsFor(GetParam().integrator, LightPaths::Exactly, 5))), 0.0)
        << "no path has more bounces than the depth";
}

TEST_P(LightPathViews, DirectPlusIndirectAndAtMostKAreTheirParts) {
    const Scene s = scene(GetParam().scene);
    const Integrator integrator = GetParam().integrator;
    ImageRgbF directPlusIndirect = render(s, settingsFor(integrator, LightPaths::Direct));
    add(directPlusIndirect, render(s, settingsFor(integrator, LightPaths::Indirect)));
    expectSameImage(directPlusIndirect, render(s, settingsFor(integrator, LightPaths::All)), "direct + indirect");

    ImageRgbF upToTwo = render(s, settingsFor(integrator, LightPaths::Exactly, 0));
    add(upToTwo, render(s, settingsFor(integrator, LightPaths::Exactly, 1)));
    add(upToTwo, render(s, settingsFor(integrator, LightPaths::Exactly, 2)));
    expectSameImage(upToTwo, render(s, settingsFor(integrator, LightPaths::AtMost, 2)), "exactly 0 + 1 + 2");
    expectSameImage(render(s, settingsFor(integrator, LightPaths::AtMost, 1)),
                    render(s, settingsFor(integrator, LightPaths::Direct)), "at most 1 = direct");
}

INSTANTIATE_TEST_SUITE_P(Scenes, LightPathViews,
                         ::testing::Values(Case{"cornell", Integrator::Full}, Case{"cornell_spheres", Integrator::Full},
                                           Case{"cornell_spheres", Integrator::Naive}, Case{"foggy_cornell", Integrator::Full}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                             return std::string(info.param.scene) + "_" + integratorName(info.param.integrator);
                         });

TEST(LightPathViews, CausticsAreBlackWithoutMirrorsOrGlass) {
    EXPECT_EQ(total(render(scene("cornell"), settingsFor(Integrator::Full, LightPaths::Caustics))), 0.0);
}

// In cornell_spheres the glass sphere focuses the light onto the floor and the mirror sphere
// throws it onto the walls: caustics are there, a part of the indirect light (a caustic has at
// least two bounces), pixel by pixel. Path tracing finds them only when a diffuse bounce's BSDF
// sample happens to pass the sphere into the small light, hence more samples.
TEST(LightPathViews, CausticsAreAPartOfTheIndirectLight) {
    const Scene s = scene("cornell_spheres");
    ImageRgbF caustics = render(s, settingsFor(Integrator::Full, LightPaths::Caustics), 64);
    ImageRgbF indirect = render(s, settingsFor(Integrator::Full, LightPaths::Indirect), 64);
    int lit = 0;
    for (std::size_t i = 0; i < caustics.rgb.size(); ++i) {
        EXPECT_LE(caustics.rgb[i], indirect.rgb[i] * (1.0f + 1e-5f) + 1e-7f) << "at float " << i;
        lit += caustics.rgb[i] > 0.0f;
    }
    EXPECT_GT(lit, 10) << "the glass sphere's caustic";
    EXPECT_LT(total(caustics), 0.5 * total(indirect));
}

// In the foggy Cornell box with black walls, light reaches the camera only straight from the light
// or scattered by the fog: were a scattering in the fog not a bounce, its light would show in the
// exactly-0 image. It shows in exactly 1 (single scattering) and 2 (double) instead; exactly 0 is
// the light seen directly, nothing below it.
TEST(LightPathViews, AScatteringInAMediumIsABounce) {
    Scene fog = parseScene(testing::foggyCornellJson(), testing::kFoggyCornellName);
    for (Material& material : fog.materials)
        if (material.type == MaterialType::Diffuse) material.color = glm::vec3(0.0f);
    const ImageRgbF none = render(fog, settingsFor(Integrator::Full, LightPaths::Exactly, 0), 16);
    const ImageRgbF single = render(fog, settingsFor(Integrator::Full, LightPaths::Exactly, 1), 16);
    const ImageRgbF twice = render(fog, settingsFor(Integrator::Full, LightPaths::Exactly, 2), 16);
    double singleBelow = 0.0;
    for (int y = kSize.y / 2; y < kSize.y; ++y) // the lower half sees the floor and the boxes, not the light
        for (int x = 0; x < kSize.x; ++x) {
            EXPECT_EQ(none.at(x, y), glm::vec3(0.0f)) << "pixel " << x << ", " << y;
            const glm::vec3 v = single.at(x, y);
            singleBelow += v.r + v.g + v.b;
        }
    EXPECT_GT(singleBelow, 0.0) << "the fog scatters the light once";
    EXPECT_GT(total(twice), 0.0) << "and twice";
    EXPECT_GT(total(none), 0.0) << "the light itself, seen through the fog";
}

TEST(LightPathViews, OnlyProgramsThatShowAPartCarryTheExplorer) {
    testing::glContext();
    PathTracer tracer;
    tracer.setScene(scene("cornell"));
    tracer.setImageSize(kSize);
    tracer.setSettings(settingsFor(Integrator::Full, LightPaths::All));
    EXPECT_EQ(tracer.pathTraceSource().source.find("nonDeltaVertices"), std::string::npos);
    EXPECT_EQ(tracer.pathTraceSource().source.find("uLightPathBounces =="), std::string::npos);
    tracer.setSettings(settingsFor(Integrator::Full, LightPaths::Caustics));
    EXPECT_NE(tracer.pathTraceSource().source.find("nonDeltaVertices"), std::string::npos);
    // k is a uniform: a new k renders with the same program.
    const int compiled = tracer.programsCompiled();
    tracer.setSettings(settingsFor(Integrator::Full, LightPaths::Exactly, 1));
    tracer.renderSample();
    tracer.setSettings(settingsFor(Integrator::Full, LightPaths::Exactly, 3));
    tracer.renderSample();
    EXPECT_EQ(tracer.programsCompiled(), compiled + 1);
}

} // namespace
} // namespace ptview
