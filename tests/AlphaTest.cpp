// Alpha MASK and BLEND on the GPU: a cut-away part lets camera rays and shadow rays through, for
// analytic quads and for meshes (the BVH walks), and BLEND lets through 1 - alpha on average.
#include "GlTestContext.h"
#include <ptview/io/ImageIO.h>
#include <ptview/tracer/PathTracer.h>
#include <ptview/scene/SceneLoader.h>
#include "TestFiles.h"

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace ptview {
namespace {

constexpr int kImageSize = 32;

ImageRgbF renderMean(const Scene& scene, RenderSettings settings, int spp) {
    testing::glContext();
    static PathTracer tracer;
    settings.sampleBudget = static_cast<std::uint32_t>(spp);
    tracer.setImageSize({kImageSize, kImageSize});
    tracer.setSettings(settings);
    tracer.setScene(scene);
    for (int i = 0; i < spp; ++i) tracer.renderSample();
    return tracer.readMean();
}

// A 2x1 base colour texture: the left texel has alpha 0 (cut away under MASK), the right 255.
ImageRgba8 halfCutAway() {
    ImageRgba8 image;
    image.width = 2;
    image.height = 1;
    image.rgba = {255, 255, 255, 0, 255, 255, 255, 255};
    return image;
}

// The cut-out: a principled quad [-1, 1]^2 (as an analytic quad or as an OBJ mesh) placed at
// `center`, facing +z.
class AlphaCutout : public ::testing::TestWithParam<const char*> {
public:
    AlphaCutout() : files_("alpha") {
        writePng(files_.write("half.png", ""), halfCutAway());
        files_.write("quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                 "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
    }
    bool mesh() const { return std::string(GetParam()) == "mesh"; }
    std::string cutout(const char* center) const {
        if (mesh())
            return std::string(R"({"type": "mesh", "mesh": "q", "material": "cut", "transform": {"translate": )") + center + "}}";
        return std::string(R"({"type": "quad", "center": )") + center + R"(, "u": [1, 0, 0], "v": [0, 1, 0], "material": "cut"})";
    }
    Scene load(const std::string& camera, const std::string& cutMaterial, const std::string& extraShapes,
               const std::string& environment) {
        return loadScene(files_.write("scene.json", R"({"camera": )" + camera + R"(,
  "environment": {"color": )" + environment + R"(},
  "meshes": {"q": {"file": "quad.obj"}},
  "materials": {"cut": )" + cutMaterial + R"(, "floor": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
  "shapes": [)" + extraShapes + "]}"));
    }

private:
    testing::ScratchFiles files_;
};

const char* const kLookDown = R"({"eye": [0, 0, 1], "target": [0, 0, 0], "up": [0, 1, 0], "vfov_deg": 90, "resolution": [32, 32]})";
const char* const kMask = R"({"type": "principled", "base_color": {"texture": "half.png", "filter": "nearest", "wrap": "clamp"},
                              "alpha_mode": "mask", "alpha_cutoff": 0.5, "roughness": 1})";

// The camera looks at the cut-out filling its view under an environment of 1: through the left
// half (cut away) it sees the environment, exactly 1; on the right half the surface (a white
// principled's reflection of the environment, below 1 since rough GGX loses energy).
TEST_P(AlphaCutout, CameraRaysPassThroughTheCutAwayHalf) {
    Scene scene = load(kLookDown, kMask, cutout("[0, 0, 0]"), "[1, 1, 1]");
    ImageRgbF image = renderMean(scene, testing::naiveSettings(1, 3u), 4);
    for (int y = 0; y < kImageSize; ++y)
        for (int x = 0; x < kImageSize; ++x) {
            if (x == kImageSize / 2 - 1 || x == kImageSize / 2) continue; // the texel edge
            float value = image.at(x, y).g;
            if (x < kImageSize / 2) ASSERT_EQ(value, 1.0f) << "cut away at " << x << ", " << y;
            else ASSERT_LT(value, 0.999f) << "there at " << x << ", " << y;
        }
}

// Shadows: a directional light travels along (-1, 0, -1) / sqrt(2) onto a diffuse floor of
// albedo 0.5 that fills the view (z = 0). The cut-out at z = 2, behind the camera, is centred at
// x = 2, so its shadow falls exactly on the floor in view: the cut-away half (its left, x < 2)
// over the floor's x < 0. There the floor is lit, 0.5 / pi * E * cos 45; under the other half it
// is in shadow, 0 (direct lighting alone, no environment: every sample gives exactly this).
Scene shadowScene(AlphaCutout& test, const std::string& cutMaterial, double irradiance) {
    Scene scene = test.load(kLookDown, cutMaterial,
                            test.cutout("[2, 0, 2]") +
                                R"(, {"type": "quad", "center": [0, 0, 0], "u": [4, 0, 0], "v": [0, 4, 0], "material": "floor"})",
                            "[0, 0, 0]");
    Light light;
    light.type = LightType::Directional;
    light.direction = glm::normalize(glm::vec3(-1, 0, -1));
    light.intensity = glm::vec3(float(irradiance));
    scene.lights.push_back(light);
    return scene;
}

RenderSettings directLighting(std::uint32_t seed) {
    RenderSettings settings;
    settings.integrator = Integrator::Direct;
    settings.maxDepth = 1;
    settings.seed = seed;
    return settings;
}

TEST_P(AlphaCutout, ShadowRaysPassThroughTheCutAwayHalf) {
    const double irradiance = 3.0;
    const double lit = 0.5 / glm::pi<double>() * irradiance * std::sqrt(0.5);
    ImageRgbF image = renderMean(shadowScene(*this, kMask, irradiance), directLighting(4u), 2);
    for (int y = 0; y < kImageSize; ++y)
        for (int x = 0; x < kImageSize; ++x) {
            if (x == kImageSize / 2 - 1 || x == kImageSize / 2) continue;
            double want = x < kImageSize / 2 ? lit : 0.0;
            ASSERT_NEAR(image.at(x, y).g, want, 1e-5 * lit) << x << ", " << y;
        }
}

// BLEND at alpha 0.5: each shadow ray passes with probability 0.5, so the floor's mean is lit / 2.
// Each of the N = 32 * 32 * spp samples is lit or 0: the image mean has standard deviation
// lit / (2 sqrt(N)); allowed: 4 of them. The half that MASK cut away is cut here too (alpha 0),
// and lit fully.
TEST_P(AlphaCutout, BlendTransmitsOneMinusAlphaOnAverage) {
    const double irradiance = 3.0;
    const double lit = 0.5 / glm::pi<double>() * irradiance * std::sqrt(0.5);
    const int spp = 8;
    const std::string blend = R"({"type": "principled", "base_color": {"texture": "half.png", "filter": "nearest", "wrap": "clamp"},
                                  "alpha_mode": "blend", "alpha": 0.5})";
    ImageRgbF image = renderMean(shadowScene(*this, blend, irradiance), directLighting(11u), spp);
    double covered = 0.0;
    int coveredCount = 0;
    for (int y = 0; y < kImageSize; ++y)
        for (int x = 0; x < kImageSize; ++x) {
            if (x == kImageSize / 2 - 1 || x == kImageSize / 2) continue;
            if (x < kImageSize / 2) {
                ASSERT_NEAR(image.at(x, y).g, lit, 1e-5 * lit) << "alpha 0 at " << x << ", " << y;
            } else {
                covered += image.at(x, y).g;
                ++coveredCount;
            }
        }
    const double mean = covered / coveredCount;
    const double sigma = lit / (2.0 * std::sqrt(double(coveredCount) * spp));
    EXPECT_NEAR(mean, 0.5 * lit, 4.0 * sigma) << "lit " << lit;
}

INSTANTIATE_TEST_SUITE_P(Shapes, AlphaCutout, ::testing::Values("quad", "mesh"),
                         [](const ::testing::TestParamInfo<const char*>& info) { return std::string(info.param); });

} // namespace
} // namespace ptview
