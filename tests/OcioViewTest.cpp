// OpenColorIO views (renderer/colour/OcioView.h) through the real display pass: the small config
// of tests/data/ocio has views whose results are known in closed form (a square root, a matrix,
// a 1D table sampled from a texture); configs, displays and views that are not there are refused
// naming the file and the name.
#include "GlTestContext.h"
#include <ptview/colour/OcioView.h>
#include <ptview/tracer/PathTracer.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

namespace ptview {
namespace {

const std::string kConfig = PTVIEW_TEST_DATA_DIR "/ocio/config.ocio";

// What the display pass writes for a constant environment seen directly (depth 0): every pixel's
// mean is `radiance`.
glm::dvec3 displayedThrough(std::shared_ptr<const OcioView> view, glm::vec3 radiance, float exposureStops = 0.0f) {
    testing::glContext();
    Scene scene;
    scene.camera.resolution = {4, 4};
    scene.environment = radiance;
    PathTracer tracer;
    tracer.setScene(scene);
    tracer.setImageSize({4, 4});
    tracer.setSettings(testing::naiveSettings(0, 1));
    tracer.renderSample();
    tracer.setOcioView(std::move(view));
    ImageRgba8 image = tracer.readToneMapped(DisplaySettings{exposureStops, ToneMapper::Ocio});
    return glm::dvec3(image.rgba[0], image.rgba[1], image.rgba[2]);
}

void expectNear8Bit(const glm::dvec3& actual, const glm::dvec3& expected01, const std::string& what) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], 255.0 * expected01[c], 1.0) << what << " channel " << c;
}

TEST(OcioView, TheConfigListsItsDisplaysAndViewsAndTheDefaultsAreTheFirst) {
    const std::vector<OcioDisplayViews> displays = OcioView::displaysAndViews(kConfig);
    ASSERT_EQ(displays.size(), 1u);
    EXPECT_EQ(displays[0].display, "test");
    EXPECT_EQ(displays[0].views, (std::vector<std::string>{"square root", "matrix", "lut"}));
    const OcioView byDefault(kConfig, "", "");
    EXPECT_EQ(byDefault.display(), "test");
    EXPECT_EQ(byDefault.view(), "square root");
    EXPECT_EQ(byDefault.label(), "config.ocio: test / square root");
}

TEST(OcioView, AnExponentViewGivesTheSquareRootOnTheGpuAndTheCpu) {
    auto view = std::make_shared<const OcioView>(kConfig, "test", "square root");
    const glm::vec3 radiance(0.25f, 0.04f, 0.81f);
    expectNear8Bit(displayedThrough(view, radiance), glm::dvec3(0.5, 0.2, 0.9), "square root");
    // Exposure comes first: +2 stops of 0.0625 is 0.25, whose square root is 0.5.
    expectNear8Bit(displayedThrough(view, glm::vec3(0.0625f), 2.0f), glm::dvec3(0.5), "exposed");
    std::vector<float> rgb = {0.25f, 0.04f, 0.81f};
    view->applyCpu(rgb);
    EXPECT_NEAR(rgb[0], 0.5f, 1e-5f);
    EXPECT_NEAR(rgb[1], 0.2f, 1e-5f);
    EXPECT_NEAR(rgb[2], 0.9f, 1e-5f);
}

TEST(OcioView, AMatrixViewScalesEachChannel) {
    auto view = std::make_shared<const OcioView>(kConfig, "test", "matrix");
    expectNear8Bit(displayedThrough(view, glm::vec3(0.8f, 0.8f, 0.4f)), glm::dvec3(0.4, 0.2, 0.4), "matrix");
}

// The table is a texture the display pass samples (OcioLuts): linear between x^2 at quarters.
TEST(OcioView, ALutViewSamplesItsTableFromATexture) {
    auto view = std::make_shared<const OcioView>(kConfig, "test", "lut");
    ASSERT_EQ(view->shader().luts.size(), 1u);
    expectNear8Bit(displayedThrough(view, glm::vec3(0.1f, 0.5f, 0.9f)), glm::dvec3(0.025, 0.25, 0.825), "lut");
}

// Blender's own config (Debian's blender-data, where installed): its Filmic view samples a 1D and
// a 3D table. The display pass must agree with OCIO's CPU processor to 8-bit rounding (the GPU
// interpolates the cube trilinearly where the CPU may use tetrahedra: 2 code values of slack).
TEST(OcioView, BlendersFilmicViewAgreesWithOciosCpuProcessor) {
    const std::string blender = "/usr/share/blender/datafiles/colormanagement/config.ocio";
    if (!std::filesystem::exists(blender)) GTEST_SKIP() << blender << " is not installed (package blender-data)";
    auto view = std::make_shared<const OcioView>(blender, "sRGB", "Filmic");
    ASSERT_FALSE(view->shader().luts.empty());
    for (const glm::vec3& radiance : {glm::vec3(0.18f), glm::vec3(0.02f, 0.5f, 3.0f), glm::vec3(12.0f, 1.0f, 0.1f)}) {
        std::vector<float> rgb = {radiance.r, radiance.g, radiance.b};
        view->applyCpu(rgb);
        const glm::dvec3 shown = displayedThrough(view, radiance);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(shown[c], 255.0 * std::clamp(double(rgb[c]), 0.0, 1.0), 2.0) << c;
    }
}

void expectOcioError(const std::function<void()>& load, const std::vector<std::string>& expected) {
    try {
        load();
        ADD_FAILURE() << "loaded";
    } catch (const OcioError& e) {
        for (const std::string& text : expected) EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << text << "\n" << e.what();
    }
}

TEST(OcioView, MissingBrokenOrIncompleteConfigsAreRefusedNamingWhatIsMissing) {
    const std::string missing = PTVIEW_TEST_DATA_DIR "/ocio/no-such.ocio";
    const std::string broken = PTVIEW_TEST_DATA_DIR "/ocio/broken.ocio";
    expectOcioError([&] { OcioView(missing, "", ""); }, {missing, "not a usable OpenColorIO config"});
    expectOcioError([&] { OcioView(broken, "", ""); }, {broken, "not a usable OpenColorIO config"});
    expectOcioError([&] { OcioView::displaysAndViews(broken); }, {broken});
    expectOcioError([&] { OcioView(kConfig, "sRGB", ""); }, {kConfig, "no display \"sRGB\"", "\"test\""});
    expectOcioError([&] { OcioView(kConfig, "test", "Filmic"); },
                    {kConfig, "has no view \"Filmic\"", "\"square root\", \"matrix\", \"lut\""});
}

// A view the display pass could not use leaves the one shown before.
TEST(OcioView, AViewCanBeReplacedAndRemoved) {
    auto sqrtView = std::make_shared<const OcioView>(kConfig, "test", "square root");
    auto matrixView = std::make_shared<const OcioView>(kConfig, "test", "matrix");
    testing::glContext();
    Scene scene;
    scene.camera.resolution = {4, 4};
    scene.environment = glm::vec3(0.25f);
    PathTracer tracer;
    tracer.setScene(scene);
    tracer.setImageSize({4, 4});
    tracer.setSettings(testing::naiveSettings(0, 1));
    tracer.renderSample();
    const DisplaySettings ocio{0.0f, ToneMapper::Ocio};
    tracer.setOcioView(sqrtView);
    EXPECT_NEAR(tracer.readToneMapped(ocio).rgba[0], 127.5, 1.0);
    tracer.setOcioView(matrixView);
    EXPECT_NEAR(tracer.readToneMapped(ocio).rgba[0], 255.0 * 0.125, 1.0);
    EXPECT_EQ(tracer.ocioView(), matrixView.get());
    tracer.setOcioView(nullptr); // Ocio without a view: the values clamped, display-encoded as they are
    EXPECT_NEAR(tracer.readToneMapped(ocio).rgba[0], 255.0 * 0.25, 1.0);
}

} // namespace
} // namespace ptview
