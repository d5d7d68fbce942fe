// The viewer's session headless: hot reload of the scene and the shaders keeps the last good
// ones and the user's edits, the split view renders both sides, screenshots land where they say.
#include <ptview/commands/SceneFromImage.h>
#include <ptview/io/ExrIO.h>
#include <ptview/gl/Readback.h>
#include "GlTestContext.h"
#include <ptview/provenance/Provenance.h>
#include <ptview/io/ImageIO.h>
#include <ptview/model/SceneInput.h>
#include <ptview/scene/MaterialTextures.h>
#include <ptview/scene/SceneLoader.h>
#include "TestFiles.h"
#include <ptview/session/UnsavedEditsPrompt.h>
#include <ptview/session/ViewerSession.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <thread>
#include <unistd.h>

namespace ptview {
namespace {

namespace fs = std::filesystem;

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream(path) << text;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

// Past the watcher's polling interval (250 ms), so the next pollFiles looks at the disk.
void waitForWatcher() {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
}

const Material& material(const ViewerSession& session, const std::string& name) {
    for (const Material& m : session.model().scene.materials)
        if (m.name == name) return m;
    throw std::runtime_error("no material " + name);
}

class ViewerSessionTest : public ::testing::Test {
protected:
    void SetUp() override { testing::glContext(); }

    std::unique_ptr<ViewerSession> openSession(const fs::path& scenePath, const fs::path& shaderDir = PTVIEW_SHADER_DIR) {
        std::optional<SceneInput> input = loadSceneInput(scenePath.string());
        EXPECT_TRUE(input);
        RenderSettings settings = testing::naiveSettings(3, 0);
        auto session = std::make_unique<ViewerSession>(std::move(*input), settings, DisplaySettings{}, shaderDir);
        session->setImageArea(PixelRect{{0, 0}, {24, 24}});
        session->update();
        return session;
    }

    // Frames until no denoise is pending: a denoise runs in bands of rows over as many frames
    // as its passes need (ViewerSession::renderFrame).
    static void renderUntilDenoised(ViewerSession& session) {
        for (int frames = 0; session.denoisePending(); ++frames) {
            ASSERT_LT(frames, 10000);
            session.renderFrame();
        }
    }

    static void renderSamples(ViewerSession& session, int samples) {
        session.update();
        while (session.stats(ViewerSession::Side::Left).samples < samples ||
               (session.comparing() && session.stats(ViewerSession::Side::Right).samples < samples))
            session.renderFrame();
    }
};

// Click-to-focus headless: a tilted wall, so that each place has its own distance along the view
// direction; the focus follows the place, and a place on the sky changes nothing.
TEST_F(ViewerSessionTest, FocusAtSetsTheDistanceOfTheSurfaceUnderThePoint) {
    testing::ScratchFiles scratch("session_focus");
    const fs::path& directory = scratch.directory();
    // The wall's plane: z = -3 - 0.5 x (it recedes to the right), for x in [-4, 0.5].
    writeText(directory / "wall.json", R"({
  "camera": {"eye": [0, 0, 0], "target": [0, 0, -1], "vfov_deg": 40, "resolution": [24, 24]},
  "environment": {"color": [0, 0, 0]},
  "materials": {"glow": {"type": "emitter", "radiance": [1, 1, 1]}},
  "shapes": [{"type": "quad", "material": "glow", "center": [-1.75, 0, -2.125], "u": [2.25, 0, -1.125], "v": [0, 3, 0]}]
})");
    std::unique_ptr<ViewerSession> session = openSession(directory / "wall.json");
    renderSamples(*session, 1);
    const float tanHalf = std::tan(glm::radians(20.0f));
    // Fractions of the image from its top-left: x = 0.5 looks straight ahead, x = 0.25 half-way to the left edge.
    for (float fraction : {0.5f, 0.25f, 0.6f}) {
        SCOPED_TRACE(fraction);
        // The ray (s, 0, -1) t, s = ndc * tan(fov / 2), meets the wall -z = 3 + 0.5 x at t = 3 / (1 - 0.5 s).
        float slope = (2.0f * fraction - 1.0f) * tanHalf;
        float depth = 3.0f / (1.0f - 0.5f * slope);
        std::optional<float> focus = session->focusAt({fraction, 0.5f});
        ASSERT_TRUE(focus);
        EXPECT_NEAR(*focus, depth, 2e-3f);
        EXPECT_EQ(session->model().scene.camera.focusDistance, *focus);
        EXPECT_TRUE(session->model().pendingChanges & ViewerModel::kCameraChanged);
        session->update();
    }
    const float before = session->model().scene.camera.focusDistance;
    EXPECT_FALSE(session->focusAt({0.98f, 0.5f})) << "the wall ends at x = 0.5: the sky there";
    EXPECT_EQ(session->model().scene.camera.focusDistance, before);
}

// Tab or a resize must not throw away an image: with samples, the render keeps its size and is
// displayed letterboxed in its own aspect ratio until the accumulation restarts anyway (R here).
// Without samples there is nothing to keep, and it follows once the size has settled.
TEST_F(ViewerSessionTest, ResizeKeepsARenderWithSamplesUntilARestart) {
    auto session = openSession(PTVIEW_ASSETS_DIR "/scenes/cornell.json");
    renderSamples(*session, 3);
    const int samples = session->stats(ViewerSession::Side::Left).samples; // a frame may hold several
    session->setImageArea(PixelRect{{10, 0}, {48, 24}}); // the sidebar hidden: a wider area
    session->update();
    EXPECT_EQ(session->renderSize(), glm::ivec2(24, 24));
    EXPECT_EQ(session->wantedRenderSize(), glm::ivec2(48, 24));
    EXPECT_EQ(session->stats(ViewerSession::Side::Left).samples, samples);
    PixelRect shown = session->displayArea();
    EXPECT_EQ(shown.size, glm::ivec2(24, 24));
    EXPECT_EQ(shown.origin, glm::ivec2(10 + 12, 0)) << "centred in the area";
    std::this_thread::sleep_for(std::chrono::milliseconds(400)); // longer than the settling time
    session->update();
    EXPECT_EQ(session->renderSize(), glm::ivec2(24, 24)) << "settling alone does not drop samples";

    session->model().pendingChanges |= ViewerModel::kRestart;
    session->update();
    EXPECT_EQ(session->renderSize(), glm::ivec2(48, 24));
    EXPECT_EQ(session->displayArea().size, glm::ivec2(48, 24));

    // No sample yet: the new size is taken once it has held for the settling time.
    session->setImageArea(PixelRect{{0, 0}, {32, 32}});
    session->update();
    EXPECT_EQ(session->renderSize(), glm::ivec2(48, 24)) << "not while the size may still be changing";
    std::this_thread::sleep_for(std::chrono::milliseconds(400));
    session->update();
    EXPECT_EQ(session->renderSize(), glm::ivec2(32, 32));
}

TEST_F(ViewerSessionTest, BrokenSceneReloadKeepsTheSceneAndEditsThenAGoodOneMergesWithThem) {
    testing::ScratchFiles scratch("session_reload");
    const fs::path& directory = scratch.directory();
    fs::path scenePath = directory / "cornell.json";
    const std::string original = testing::readFileBytes(PTVIEW_ASSETS_DIR "/scenes/cornell.json");
    writeText(scenePath, original);
    auto session = openSession(scenePath);
    renderSamples(*session, 2);

    // The user's edit in the UI.
    for (Material& m : session->model().scene.materials)
        if (m.name == "white") m.color = glm::vec3(0.2f, 0.7f, 0.2f);
    session->model().pendingChanges |= ViewerModel::kMaterialsChanged;
    renderSamples(*session, 2);

    // A save that breaks the file: the error names it, the scene and the edit stay, and it renders on.
    waitForWatcher();
    writeText(scenePath, original.substr(0, original.size() / 2));
    int reloads = session->reloadCount();
    session->pollFiles();
    EXPECT_EQ(session->reloadCount(), reloads + 1);
    EXPECT_NE(session->model().sceneError.find(scenePath.string()), std::string::npos) << session->model().sceneError;
    EXPECT_EQ(material(*session, "white").color, glm::vec3(0.2f, 0.7f, 0.2f));
    EXPECT_EQ(session->model().scene.shapes.size(), loadScene(PTVIEW_ASSETS_DIR "/scenes/cornell.json").shapes.size());
    int samples = session->stats(ViewerSession::Side::Left).samples;
    renderSamples(*session, samples + 1);

    // The file fixed, with a brighter light: the light comes from the file, the edit survives.
    waitForWatcher();
    writeText(scenePath, replaced(original, "[17.0, 12.0, 4.0]", "[34.0, 24.0, 8.0]"));
    session->pollFiles();
    EXPECT_EQ(session->model().sceneError, "");
    EXPECT_EQ(material(*session, "light").radiance, glm::vec3(34.0f, 24.0f, 8.0f));
    EXPECT_EQ(material(*session, "white").color, glm::vec3(0.2f, 0.7f, 0.2f));
    session->update();
    EXPECT_EQ(session->stats(ViewerSession::Side::Left).samples, 0) << "a reload restarts accumulation";
}

TEST_F(ViewerSessionTest, BrokenShaderReloadKeepsTheLastGoodProgram) {
    testing::ScratchFiles scratch("session_shaders");
    const fs::path& directory = scratch.directory();
    fs::copy(PTVIEW_SHADER_DIR, directory, fs::copy_options::recursive);
    fs::path scenePath = fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json";
    auto session = openSession(scenePath, directory);
    renderSamples(*session, 1);

    const std::string goodToneMap = testing::readFileBytes(directory / "tonemap.glsl");
    waitForWatcher();
    writeText(directory / "tonemap.glsl", goodToneMap + "\nthis is not GLSL;\n");
    session->pollFiles();
    const std::string& error = session->model().shaderError;
    EXPECT_NE(error.find("tonemap.glsl:"), std::string::npos) << "the error names the file and line: " << error;
    int samples = session->stats(ViewerSession::Side::Left).samples;
    renderSamples(*session, samples + 2); // the old program still renders

    waitForWatcher();
    writeText(directory / "tonemap.glsl", goodToneMap);
    session->pollFiles();
    EXPECT_EQ(session->model().shaderError, "");
    EXPECT_NE(session->model().notice.find("shaders reloaded"), std::string::npos);
    renderSamples(*session, 1);
}

// Equal time means equal time from the first frame: turning the split view on restarts the left
// side too, instead of letting it keep the samples it had before (which it did).
TEST_F(ViewerSessionTest, TurningTheSplitViewOnRestartsBothSides) {
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    ViewerModel& model = session->model();
    renderSamples(*session, 4);
    ASSERT_GE(session->stats(ViewerSession::Side::Left).samples, 4);

    model.compare.enabled = true;
    session->update();
    ASSERT_TRUE(session->comparing());
    EXPECT_EQ(session->stats(ViewerSession::Side::Left).samples, 0);
    EXPECT_EQ(session->stats(ViewerSession::Side::Right).samples, 0);
    EXPECT_EQ(session->stats(ViewerSession::Side::Left).renderSeconds, 0.0);

    // Off, the left side goes on alone; on again, both start afresh (the right one had samples).
    renderSamples(*session, 2);
    model.compare.enabled = false;
    renderSamples(*session, 5);
    model.compare.enabled = true;
    session->update();
    EXPECT_EQ(session->stats(ViewerSession::Side::Left).samples, 0);
    EXPECT_EQ(session->stats(ViewerSession::Side::Right).samples, 0);
    // Staying on restarts nothing.
    renderSamples(*session, 1);
    session->update();
    EXPECT_GE(session->stats(ViewerSession::Side::Left).samples, 1);
}

// Grid and stratified without a target run past their pattern into patches; choosing one sets
// the target where the pattern is complete, and says so. A target the user set stays theirs.
TEST_F(ViewerSessionTest, ChoosingAPatternSamplerWithoutATargetSetsOne) {
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    ViewerModel& model = session->model();
    ASSERT_EQ(model.targetSamples, 0);
    model.settings.sampler = SamplerMode::Sobol; // unbiased at any count: no target
    session->update();
    EXPECT_EQ(model.targetSamples, 0);

    model.settings.sampler = SamplerMode::Grid;
    session->update();
    EXPECT_EQ(model.targetSamples, kPatternTargetSamples);
    EXPECT_NE(model.notice.find(std::to_string(kPatternTargetSamples) + " spp"), std::string::npos) << model.notice;
    EXPECT_EQ(session->settings(ViewerSession::Side::Left).sampleBudget, std::uint32_t(kPatternTargetSamples));

    model.targetSamples = 0; // cleared by the user: stays cleared while the sampler stays
    session->update();
    session->update();
    EXPECT_EQ(model.targetSamples, 0);

    model.targetSamples = 64;
    model.settings.sampler = SamplerMode::Stratified;
    session->update();
    EXPECT_EQ(model.targetSamples, 64);

    // The split view's right side counts as a choice too, once it is shown.
    model.targetSamples = 0;
    model.compare.right.sampler = SamplerMode::Grid;
    session->update();
    EXPECT_EQ(model.targetSamples, 0) << "the right side is not shown yet";
    model.compare.enabled = true;
    session->update();
    EXPECT_EQ(model.targetSamples, kPatternTargetSamples);
}

TEST_F(ViewerSessionTest, SplitViewRendersBothSidesWithTheirOwnSettings) {
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    ViewerModel& model = session->model();
    model.settings.integrator = Integrator::Naive;
    model.compare.enabled = true;
    model.compare.equalTime = false; // equal samples: both sides advance together
    model.compare.right.integrator = Integrator::Mis;
    renderSamples(*session, 3);
    ASSERT_TRUE(session->comparing());
    int left = session->stats(ViewerSession::Side::Left).samples;
    int right = session->stats(ViewerSession::Side::Right).samples;
    EXPECT_LE(std::abs(left - right), 1);
    EXPECT_EQ(session->settings(ViewerSession::Side::Left).integrator, Integrator::Naive);
    EXPECT_EQ(session->settings(ViewerSession::Side::Right).integrator, Integrator::Mis);

    testing::ScratchFiles scratch("session_compare");
    const fs::path& directory = scratch.directory();
    std::vector<fs::path> files = session->saveScreenshots(directory);
    ASSERT_EQ(files.size(), 6u); // PNG, PFM and EXR of each side
    ImageRgbF naive = readPfm(files[1]), mis = readPfm(files[4]);
    EXPECT_NE(files[1].filename().string().find("cornell-"), std::string::npos);
    EXPECT_NE(files[1].filename().string().find("-left.pfm"), std::string::npos);
    EXPECT_NE(naive.rgb, mis.rgb) << "two integrators, two images";
    // The EXR holds the PFM's pixels, and each side's file its own settings (Provenance.h).
    EXPECT_EQ(files[2].extension(), ".exr");
    EXPECT_EQ(exrRgb(readExr(files[2]), files[2].string()).rgb, naive.rgb);
    EXPECT_EQ(exrRgb(readExr(files[5]), files[5].string()).rgb, mis.rgb);
    EXPECT_EQ(readProvenance(files[2]).recipe.settings.integrator, Integrator::Naive);
    EXPECT_EQ(readProvenance(files[5]).recipe.settings.integrator, Integrator::Mis);
    EXPECT_EQ(readProvenance(files[3]).recipe.settings.integrator, Integrator::Mis); // the PNG
    EXPECT_EQ(readProvenance(files[2]).recipe.samplesPerPixel, left);
}

TEST_F(ViewerSessionTest, TargetSamplesStopsAccumulationAtExactlyTheTarget) {
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    session->model().targetSamples = 5;
    session->update();
    for (int frame = 0; frame < 200 && session->accumulating(); ++frame) session->renderFrame();
    EXPECT_FALSE(session->accumulating());
    EXPECT_EQ(session->stats(ViewerSession::Side::Left).samples, 5);
    session->renderFrame();
    EXPECT_EQ(session->stats(ViewerSession::Side::Left).samples, 5);
}

// A target error makes the main view sample adaptively, as `render --noise-threshold` does: it
// stops with the estimate at or below the target (or with every pixel stopped), a pixel stopped
// at a check takes no more samples, none stops before kAdaptiveMinSamples, and a new target
// starts the accumulation and its checks over.
TEST_F(ViewerSessionTest, TargetErrorStopsAdaptivelyAndStoppedPixelsTakeNoMoreSamples) {
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    const double target = 0.05;
    session->model().targetErrorOn = true;
    session->model().targetError = static_cast<float>(target);
    session->update();
    const PathTracer& tracer = session->tracer(ViewerSession::Side::Left);
    std::vector<int> countWhenStopped(24 * 24, -1);
    int framesWithStoppedPixels = 0;
    for (int frame = 0; frame < 20000 && session->accumulating(); ++frame) {
        session->renderFrame();
        PixelStatistics statistics = tracer.readStatistics();
        if (tracer.sampleCount() == 0) continue; // a loaded machine may spread the first pass over frames
        ASSERT_EQ(statistics.pixelSampleCounts.size(), countWhenStopped.size());
        bool anyStopped = false;
        for (std::size_t i = 0; i < countWhenStopped.size(); ++i) {
            if (statistics.pixelTakesSamples[i]) {
                EXPECT_EQ(countWhenStopped[i], -1) << "pixel " << i << " took samples again after it stopped";
                continue;
            }
            anyStopped = true;
            EXPECT_GE(statistics.pixelSampleCounts[i], kAdaptiveMinSamples) << "pixel " << i;
            if (countWhenStopped[i] < 0) countWhenStopped[i] = statistics.pixelSampleCounts[i];
            EXPECT_EQ(statistics.pixelSampleCounts[i], countWhenStopped[i]) << "stopped pixel " << i << " took more samples";
        }
        framesWithStoppedPixels += anyStopped ? 1 : 0;
    }
    ASSERT_FALSE(session->accumulating()) << "adaptive sampling never stopped";
    ViewerSession::ViewStats stats = session->stats(ViewerSession::Side::Left);
    ASSERT_TRUE(stats.adaptive);
    const ViewerSession::ViewStats::Adaptive& adaptive = *stats.adaptive;
    EXPECT_TRUE(adaptive.finished);
    const bool reached = adaptive.estimate.reliable && relativeError(adaptive.estimate.relativeMse) <= target;
    EXPECT_TRUE(reached || adaptive.samples.stoppedShare >= 1.0)
        << "estimate " << relativeError(adaptive.estimate.relativeMse) << ", stopped share " << adaptive.samples.stoppedShare;
    EXPECT_GE(adaptive.checks, 2);
    EXPECT_EQ(adaptive.samples.max, tracer.sampleCount());
    EXPECT_LE(adaptive.samples.min, adaptive.samples.max);
    EXPECT_NE(adaptive.note.find("stopped: "), std::string::npos) << adaptive.note;
    if (reached) {
        EXPECT_NE(adaptive.note.find("<= 5%"), std::string::npos) << adaptive.note;
    }
    // Finished means finished: further frames add nothing.
    const int samples = tracer.sampleCount();
    session->renderFrame();
    EXPECT_EQ(tracer.sampleCount(), samples);
    // A screenshot of it carries the threshold, so `render --from` samples it adaptively too.
    testing::ScratchFiles scratch("session_adaptive");
    const fs::path& directory = scratch.directory();
    std::vector<fs::path> files = session->saveScreenshots(directory);
    ASSERT_EQ(files.size(), 3u);
    const RenderRecipe recipe = readProvenance(files[2]).recipe;
    ASSERT_TRUE(recipe.noiseThreshold);
    EXPECT_FLOAT_EQ(*recipe.noiseThreshold, 0.05f);
    EXPECT_EQ(recipe.samplesPerPixel, samples);

    // A new target restarts, with the checks from the start.
    session->model().targetError = 0.2f;
    session->update();
    EXPECT_EQ(tracer.sampleCount(), 0);
    EXPECT_EQ(session->stats(ViewerSession::Side::Left).adaptive->checks, 0);
    EXPECT_TRUE(session->accumulating());
    // Off: every pixel samples again, without a target.
    session->model().targetErrorOn = false;
    session->update();
    EXPECT_FALSE(session->stats(ViewerSession::Side::Left).adaptive);
    renderSamples(*session, 70);
    PixelStatistics statistics = tracer.readStatistics();
    for (std::size_t i = 0; i < statistics.pixelTakesSamples.size(); ++i) ASSERT_TRUE(statistics.pixelTakesSamples[i]);
}

// Adaptive against uniform at equal time: two renders with the same settings, the left with a
// target error; when the left stops, the right (uniform: no pixel stops) stops at the same GPU
// time, within the last tile.
TEST_F(ViewerSessionTest, WithATargetErrorTheSplitViewsUniformSideStopsAtTheAdaptiveSidesTime) {
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    ViewerModel& model = session->model();
    model.compare.enabled = true;
    session->update();
    model.compare.right = model.settings; // the first comparison chose another integrator
    model.compare.equalTime = true;
    model.targetErrorOn = true;
    renderSamples(*session, 2);
    model.targetError = 0.1f;
    session->update();
    ASSERT_TRUE(session->comparesTwoRenders());
    EXPECT_EQ(session->stats(ViewerSession::Side::Right).samples, 0) << "a new target starts both sides together";
    for (int frame = 0; frame < 20000 && session->accumulating(); ++frame) session->renderFrame();
    ASSERT_FALSE(session->accumulating());
    ViewerSession::ViewStats left = session->stats(ViewerSession::Side::Left), right = session->stats(ViewerSession::Side::Right);
    ASSERT_TRUE(left.adaptive);
    EXPECT_TRUE(left.adaptive->finished);
    EXPECT_FALSE(right.adaptive) << "the right side samples uniformly";
    EXPECT_GT(right.samples, 0);
    EXPECT_GE(right.renderSeconds, left.renderSeconds);
    EXPECT_LT(right.renderSeconds, left.renderSeconds + 0.25) << "it stops within a tile of the left's time";
    PixelStatistics statistics = session->tracer(ViewerSession::Side::Right).readStatistics();
    for (std::uint8_t takes : statistics.pixelTakesSamples) ASSERT_TRUE(takes);
}

// The error (estimate and true error) is measured about once a second, not every frame: the
// Stats panel printed a 2-spp figure beside "16 spp". Each figure carries the count and the
// seconds it was measured at, which the panels print beside it.
TEST_F(ViewerSessionTest, ErrorFiguresCarryTheSppTheyWereMeasuredAt) {
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    session->model().maxSamplesPerFrame = 1;
    session->update();
    int measuredAt = 0;
    bool sawAnOlderFigure = false;
    auto start = std::chrono::steady_clock::now();
    for (int frame = 0; frame < 400 && std::chrono::steady_clock::now() - start < std::chrono::seconds(3); ++frame) {
        session->renderFrame();
        ViewerSession::ViewStats stats = session->stats(ViewerSession::Side::Left);
        ASSERT_LE(stats.errorSamples, stats.samples);
        ASSERT_LE(stats.errorSeconds, stats.renderSeconds);
        if (stats.errorSamples != measuredAt) {
            // A new measurement happens at the end of a frame: of the samples that frame left.
            EXPECT_EQ(stats.errorSamples, stats.samples);
            EXPECT_EQ(stats.errorSeconds, stats.renderSeconds);
            measuredAt = stats.errorSamples;
        }
        if (measuredAt >= 2 && stats.samples > stats.errorSamples) {
            sawAnOlderFigure = true;
            EXPECT_LT(stats.errorSeconds, stats.renderSeconds);
        }
    }
    EXPECT_GE(measuredAt, 2) << "an estimate was made";
    EXPECT_TRUE(sawAnOlderFigure) << "between measurements the figure is of fewer samples than the image, and says so";
}

TEST_F(ViewerSessionTest, UnreadableSceneOrMapLeavesTheCurrentSceneAlone) {
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    size_t shapes = session->model().scene.shapes.size();
    EXPECT_FALSE(session->openScene("/nonexistent/scene.json"));
    EXPECT_NE(session->model().sceneError.find("/nonexistent/scene.json"), std::string::npos);
    EXPECT_FALSE(session->setEnvironmentMap("/nonexistent/sky.hdr"));
    EXPECT_NE(session->model().sceneError.find("/nonexistent/sky.hdr"), std::string::npos);
    EXPECT_EQ(session->model().scene.shapes.size(), shapes);
    EXPECT_TRUE(session->model().scene.environmentMap.empty());
    renderSamples(*session, 1);
}

// A reference with one NaN (or infinite) pixel made every true-error figure NaN. It is refused
// with the file and the pixel named, and the reference loaded before stays.
TEST_F(ViewerSessionTest, ReferenceWithANonFinitePixelIsRefusedNamingThePixel) {
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    testing::ScratchFiles files("session_reference");
    ImageRgbF image;
    image.width = 24, image.height = 24;
    image.rgb.assign(24 * 24 * 3, 0.5f);
    const fs::path good = files.write("good.pfm", "");
    writePfm(good, image);
    ASSERT_TRUE(session->setReference(good)) << session->model().sceneError;
    for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        image.rgb[(5 * 24 + 7) * 3 + 1] = bad; // pixel (7, 5), green
        const fs::path path = files.write(std::isnan(bad) ? "nan.pfm" : "inf.pfm", "");
        writePfm(path, image);
        EXPECT_FALSE(session->setReference(path));
        const std::string& error = session->model().sceneError;
        EXPECT_EQ(error.rfind(path.string() + ": pixel (7, 5) is " + (std::isnan(bad) ? "NaN" : "infinite"), 0), 0u)
            << error;
        EXPECT_NE(error.find("1 of 576 pixels"), std::string::npos) << error;
        ASSERT_TRUE(session->model().reference);
        EXPECT_EQ(session->model().referencePath, good);
    }
}

double imageMean(const ImageRgbF& image) {
    double sum = 0.0;
    for (float v : image.rgb) sum += v;
    return sum / static_cast<double>(image.rgb.size());
}

TEST_F(ViewerSessionTest, EnvironmentMapAndLightEditsReachTheRenderer) {
    testing::ScratchFiles scratch("session_lights");
    const fs::path& directory = scratch.directory();
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/lights.json");
    ViewerModel& model = session->model();
    ASSERT_FALSE(model.scene.lights.empty());
    model.settings.integrator = Integrator::Full; // naive never finds point and spot lights
    model.targetSamples = 8; // exactly 8 each time (a frame may hold several passes), so same seed, same image
    auto meanAfter = [&](int samples) {
        renderSamples(*session, samples);
        session->writeImage(ViewerSession::Side::Left, directory / "image.pfm");
        return imageMean(readPfm(directory / "image.pfm"));
    };
    double lit = meanAfter(8);

    // Every point and spot light off: only the area lights remain, so the image darkens.
    for (Light& light : model.scene.lights) light.intensity = glm::vec3(0.0f);
    model.pendingChanges |= ViewerModel::kSceneChanged;
    session->update();
    EXPECT_EQ(session->stats(ViewerSession::Side::Left).samples, 0);
    double dimmed = meanAfter(8);
    EXPECT_LT(dimmed, 0.9 * lit);

    // An HDR map from assets/ adds its light; its intensity scales that contribution.
    ASSERT_TRUE(session->setEnvironmentMap(fs::path(PTVIEW_ASSETS_DIR) / "hdr/studio_small_03_1k.hdr"));
    EXPECT_EQ(model.sceneError, "");
    double withMap = meanAfter(8);
    EXPECT_GT(withMap, dimmed * 1.05);
    model.scene.environmentIntensity = 0.0f;
    model.pendingChanges |= ViewerModel::kSceneChanged;
    // A map at intensity 0 adds no light and takes no light samples: the very image without it.
    double mapOff = meanAfter(8);
    EXPECT_NEAR(mapOff, dimmed, 1e-6 * dimmed);
}

TEST_F(ViewerSessionTest, UnsavedEditsAreKnownUntilSavedAndTheSavedFileIsTheOneWatched) {
    testing::ScratchFiles scratch("session_unsaved");
    const fs::path& directory = scratch.directory();
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    ViewerModel& model = session->model();
    EXPECT_FALSE(session->hasUnsavedEdits());
    EXPECT_EQ(session->unsavedEdits(), std::vector<std::string>{});
    model.scene.camera.eye.x += 0.5f; // a view the user set up is work too
    EXPECT_TRUE(session->hasUnsavedEdits());
    EXPECT_EQ(session->unsavedEdits(), std::vector<std::string>{"camera"});
    session->resetCamera();
    EXPECT_FALSE(session->hasUnsavedEdits()) << "the file's camera again";
    model.scene.materials[0].color *= 0.5f;
    model.scene.environment = glm::vec3(0.2f); // the colour: without a map the file keeps no intensity
    EXPECT_TRUE(session->hasUnsavedEdits());
    EXPECT_EQ(session->unsavedEdits(), (std::vector<std::string>{"materials", "environment"}));

    fs::path saved = directory / "mine.json";
    session->saveSceneAs(saved);
    EXPECT_FALSE(session->hasUnsavedEdits());
    EXPECT_EQ(model.fileScene.path, saved);
    // An edit of the saved file on disk now reloads, merged with the scene as saved.
    waitForWatcher();
    writeText(saved, replaced(testing::readFileBytes(saved), "[17, 12, 4]", "[1, 1, 1]")); // the light's radiance
    session->pollFiles();
    EXPECT_EQ(model.sceneError, "");
    EXPECT_EQ(material(*session, "light").radiance, glm::vec3(1.0f));
    EXPECT_EQ(model.scene.materials[0].color, model.fileScene.materials[0].color);
}

// A material a glTF file made is saved as an override in the scene file's reference to the glTF
// (it used to stay an unsaved edit that Save could not keep): after Save nothing is unsaved (the
// title loses its *), and the saved file opens with the edit.
TEST_F(ViewerSessionTest, EditsToGltfMaterialsAreSavedAsOverrides) {
    testing::ScratchFiles scratch("session_gltf_edits");
    const fs::path& directory = scratch.directory();
    auto session = openSession(PTVIEW_ASSETS_DIR "/scenes/helmet.json");
    ViewerModel& model = session->model();
    auto imported = std::find_if(model.scene.materials.begin(), model.scene.materials.end(),
                                 [](const Material& m) { return m.importedFrom >= 0; });
    ASSERT_NE(imported, model.scene.materials.end());
    const std::string name = imported->name;
    EXPECT_FALSE(session->hasUnsavedEdits());
    const float metallic = imported->metallic == 0.25f ? 0.5f : 0.25f;
    imported->metallic = metallic;
    EXPECT_TRUE(session->hasUnsavedEdits());
    EXPECT_EQ(session->unsavedEdits(), std::vector<std::string>{"materials"});

    const fs::path saved = directory / "helmet.json";
    session->saveSceneAs(saved);
    EXPECT_FALSE(session->hasUnsavedEdits()) << "the edit is in the file";
    EXPECT_EQ(model.fileScene.path, saved);
    // The helmet's metallic comes from its texture, which the override keeps.
    const nlohmann::json written = nlohmann::json::parse(testing::readFileBytes(saved));
    EXPECT_EQ(written["gltf"][0]["materials"], (nlohmann::json{{name, {{"metallic", {{"factor", metallic}}}}}}))
        << written["gltf"].dump();
    const Scene reopened = loadScene(saved);
    auto again = std::find_if(reopened.materials.begin(), reopened.materials.end(),
                              [&](const Material& m) { return m.name == name; });
    ASSERT_NE(again, reopened.materials.end());
    EXPECT_EQ(again->metallic, metallic);
    EXPECT_EQ(again->importedFrom, 0) << "still the glTF file's material";
}

// A scene an image carries (SceneInput::carriedBy) has no file of its own, whatever its
// ptview.scene_file says: no save target, nothing watched, and an edit answered with Save in the
// unsaved-edits question writes nothing (it asks for a name) and leaves the named file alone.
TEST_F(ViewerSessionTest, ASceneCarriedByAnImageHasNoSaveTarget) {
    testing::ScratchFiles scratch("session_carried");
    const fs::path& directory = scratch.directory();
    const fs::path notes = directory / "notes.txt";
    writeText(notes, "my notes\n");
    std::optional<SceneInput> input = loadSceneInput(PTVIEW_ASSETS_DIR "/scenes/cornell.json");
    ASSERT_TRUE(input);
    input->scene.path = notes; // what the sender wrote in ptview.scene_file
    input->carriedBy = directory / "shot.png";
    ViewerSession session(std::move(*input), testing::naiveSettings(3, 0), DisplaySettings{}, PTVIEW_SHADER_DIR);
    EXPECT_EQ(session.saveTarget(), "");
    EXPECT_TRUE(session.model().fileScene.path.empty());
    EXPECT_TRUE(session.hasUnsavedEdits()) << "the named file does not hold the image's scene: only the image does";
    EXPECT_NE(session.model().notice.find("shot.png"), std::string::npos) << session.model().notice;
    session.model().scene.materials[0].color *= 0.5f;
    EXPECT_TRUE(session.hasUnsavedEdits());
    UnsavedEditsPrompt prompt;
    prompt.request(session, UnsavedEditsPrompt::Action::Quit);
    prompt.answer(session, UnsavedEditsPrompt::Answer::Save);
    EXPECT_FALSE(prompt.quitConfirmed());
    EXPECT_NE(prompt.saveError().find("no file to save to"), std::string::npos) << prompt.saveError();
    EXPECT_EQ(testing::readFileBytes(notes), "my notes\n");
}

// Opening a screenshot: the scene it carries counts as unsaved (the star; Save asks for a name)
// unless the file it names holds it as it is. A lens the user set before the screenshot is such a
// difference; the named file is read only inside the image's folder, as the scene's files are.
TEST_F(ViewerSessionTest, AScreenshotsSceneIsUnsavedUnlessTheFileItNamesHoldsIt) {
    testing::ScratchFiles scratch("session_screenshot-star");
    const fs::path& directory = scratch.directory();
    fs::copy_file(PTVIEW_ASSETS_DIR "/scenes/cornell.json", directory / "scene.json");
    fs::create_directories(directory / "elsewhere");
    auto session = openSession(directory / "scene.json");
    renderSamples(*session, 1);
    session->writeImage(ViewerSession::Side::Left, directory / "same.png");
    fs::copy_file(directory / "same.png", directory / "elsewhere" / "same.png");
    session->model().scene.camera.apertureRadius = 0.05f;
    session->model().pendingChanges |= ViewerModel::kCameraChanged;
    renderSamples(*session, 1);
    session->writeImage(ViewerSession::Side::Left, directory / "lens.png");

    struct Case {
        fs::path image;
        bool unsaved;
        const char* why;
    };
    for (const Case& c : {Case{directory / "same.png", false, "scene.json holds the image's scene"},
                          Case{directory / "lens.png", true, "the lens differs from scene.json"},
                          Case{directory / "elsewhere" / "same.png", true, "scene.json is outside the image's folder: unread"}}) {
        SCOPED_TRACE(c.why);
        std::optional<Provenance> provenance;
        std::optional<SceneInput> input = loadSceneInputFromImage(c.image.string(), provenance);
        ASSERT_TRUE(input);
        EXPECT_EQ(input->carriedSceneIsInItsFile, !c.unsaved);
        ViewerSession opened(std::move(*input), testing::naiveSettings(3, 0), DisplaySettings{}, PTVIEW_SHADER_DIR);
        EXPECT_EQ(opened.hasUnsavedEdits(), c.unsaved);
        EXPECT_EQ(opened.unsavedEdits(), c.unsaved ? std::vector<std::string>{"scene"} : std::vector<std::string>{});
        EXPECT_EQ(opened.saveTarget(), "") << "still no save target (docs/robustness.md)";
        if (c.unsaved) {
            opened.saveSceneAs(directory / "saved.json");
            EXPECT_FALSE(opened.hasUnsavedEdits()) << "saved";
        }
    }
}

// Save to a.json, then open another scene: Save must now write that scene's own file, not a.json
// (the Materials panel kept the first path it showed, and a Save replaced the edited a.json with
// the other scene). What the user types after opening is the target until the next open or save.
TEST_F(ViewerSessionTest, SaveTargetFollowsTheOpenScene) {
    testing::ScratchFiles scratch("session_target");
    const fs::path& directory = scratch.directory();
    fs::copy_file(PTVIEW_ASSETS_DIR "/scenes/cornell.json", directory / "cornell.json");
    fs::copy_file(PTVIEW_ASSETS_DIR "/scenes/materials.json", directory / "materials.json");
    auto session = openSession(directory / "cornell.json");
    EXPECT_EQ(session->saveTarget(), (directory / "cornell.json").string());
    session->model().scene.materials[0].color *= 0.5f;
    session->saveSceneAs(directory / "a.json");
    EXPECT_EQ(session->saveTarget(), (directory / "a.json").string());

    ASSERT_TRUE(session->openScene(directory / "materials.json"));
    EXPECT_EQ(session->saveTarget(), (directory / "materials.json").string());
    EXPECT_FALSE(session->saveReplacesAnotherFile(directory / "materials.json")) << "its own file";
    EXPECT_TRUE(session->saveReplacesAnotherFile(directory / "a.json")) << "the edited cornell box";
    EXPECT_FALSE(session->saveReplacesAnotherFile(directory / "new.json")) << "nothing to replace";

    session->setSaveTarget((directory / "typed.json").string());
    EXPECT_EQ(session->saveTarget(), (directory / "typed.json").string()) << "what the user typed stays";
    EXPECT_FALSE(session->openScene(directory / "missing.json"));
    EXPECT_EQ(session->saveTarget(), (directory / "typed.json").string()) << "a failed open changes nothing";
    ASSERT_TRUE(session->openScene(directory / "a.json"));
    EXPECT_EQ(session->saveTarget(), (directory / "a.json").string());
}

TEST_F(ViewerSessionTest, QuitWaitsForAnAnswerOnlyWhenThereAreUnsavedEdits) {
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    UnsavedEditsPrompt clean;
    clean.request(*session, UnsavedEditsPrompt::Action::Quit);
    EXPECT_TRUE(clean.quitConfirmed()) << "nothing to lose: no question";
    EXPECT_FALSE(clean.pending());

    session->model().scene.camera.eye.y += 0.25f;
    UnsavedEditsPrompt prompt;
    prompt.request(*session, UnsavedEditsPrompt::Action::Quit);
    EXPECT_FALSE(prompt.quitConfirmed());
    ASSERT_TRUE(prompt.pending());
    EXPECT_EQ(*prompt.pending(), UnsavedEditsPrompt::Action::Quit);
    prompt.answer(*session, UnsavedEditsPrompt::Answer::Cancel);
    EXPECT_FALSE(prompt.pending());
    EXPECT_FALSE(prompt.quitConfirmed());
    EXPECT_TRUE(session->hasUnsavedEdits()) << "Cancel keeps everything";
    prompt.request(*session, UnsavedEditsPrompt::Action::Quit);
    prompt.answer(*session, UnsavedEditsPrompt::Answer::Discard);
    EXPECT_TRUE(prompt.quitConfirmed());
}

TEST_F(ViewerSessionTest, SaveAnswerWritesTheEditsBeforeOpeningAnotherScene) {
    testing::ScratchFiles scratch("session_prompt_save");
    const fs::path& directory = scratch.directory();
    fs::path scenePath = directory / "cornell.json";
    fs::copy_file(PTVIEW_ASSETS_DIR "/scenes/cornell.json", scenePath);
    auto session = openSession(scenePath);
    const fs::path other = fs::path(PTVIEW_ASSETS_DIR) / "scenes/materials.json";
    UnsavedEditsPrompt prompt;
    session->model().scene.materials[0].color = glm::vec3(0.25f, 0.5f, 0.75f);
    prompt.request(*session, UnsavedEditsPrompt::Action::OpenScene, other);
    ASSERT_TRUE(prompt.pending());
    EXPECT_EQ(session->model().fileScene.path, scenePath) << "nothing opened yet";

    // A save that cannot be written keeps the question, the scene and the edits.
    session->setSaveTarget((directory / "no such directory" / "x.json").string());
    prompt.answer(*session, UnsavedEditsPrompt::Answer::Save);
    EXPECT_TRUE(prompt.pending());
    EXPECT_NE(prompt.saveError().find("x.json"), std::string::npos) << prompt.saveError();
    EXPECT_EQ(session->model().fileScene.path, scenePath);
    EXPECT_TRUE(session->hasUnsavedEdits());

    session->setSaveTarget(scenePath.string());
    prompt.answer(*session, UnsavedEditsPrompt::Answer::Save);
    EXPECT_FALSE(prompt.pending());
    EXPECT_EQ(loadScene(scenePath).materials[0].color, glm::vec3(0.25f, 0.5f, 0.75f)) << "the edit is in the file";
    EXPECT_EQ(session->model().fileScene.path, other) << "then the other scene opened";
    EXPECT_FALSE(session->hasUnsavedEdits());
}

TEST_F(ViewerSessionTest, DiscardOpensTheOtherSceneAndReloadDiscardReadsTheFileAsItIs) {
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    const Scene file = session->model().fileScene;
    UnsavedEditsPrompt prompt;

    // Reload with an edit the file did not change: the merge would keep it, so only Discard drops it.
    session->model().scene.materials[0].color = glm::vec3(0.25f, 0.5f, 0.75f);
    prompt.request(*session, UnsavedEditsPrompt::Action::Reload);
    ASSERT_TRUE(prompt.pending());
    EXPECT_EQ(session->model().scene.materials[0].color, glm::vec3(0.25f, 0.5f, 0.75f));
    prompt.answer(*session, UnsavedEditsPrompt::Answer::Discard);
    EXPECT_FALSE(prompt.pending());
    EXPECT_EQ(session->model().scene.materials[0].color, file.materials[0].color);
    EXPECT_FALSE(session->hasUnsavedEdits());

    const fs::path other = fs::path(PTVIEW_ASSETS_DIR) / "scenes/materials.json";
    session->model().scene.environment = glm::vec3(0.1f);
    session->model().scene.camera.vfovDeg = 30.0f;
    prompt.request(*session, UnsavedEditsPrompt::Action::OpenScene, other);
    ASSERT_TRUE(prompt.pending());
    EXPECT_EQ(prompt.sceneToOpen(), other);
    prompt.answer(*session, UnsavedEditsPrompt::Answer::Discard);
    EXPECT_EQ(session->model().fileScene.path, other);
    EXPECT_EQ(session->model().scene.shapes.size(), loadScene(other).shapes.size());
    EXPECT_FALSE(prompt.quitConfirmed());
}

// The paths traced for a pixel of the view are the samples the view added to it: their mean is the
// pixel's value (the same samples, to float rounding), with the view's integrator, depth and size.
TEST_F(ViewerSessionTest, TracedPathsAreTheSamplesOfTheViewsPixel) {
    std::unique_ptr<ViewerSession> session = openSession(PTVIEW_ASSETS_DIR "/scenes/cornell.json");
    session->model().settings.integrator = Integrator::Full;
    renderSamples(*session, 8);
    const int spp = session->stats(ViewerSession::Side::Left).samples;
    const glm::ivec2 pixel{6, 21}; // of 24x24: the floor, left of the boxes
    const ViewerSession::TracedPaths& traced = session->tracePaths(pixel, spp);
    ASSERT_EQ(traced.paths.size(), static_cast<size_t>(spp));
    EXPECT_EQ(traced.settings.integrator, Integrator::Full);
    EXPECT_EQ(traced.imageSize, glm::ivec2(24, 24));
    glm::vec3 mean(0.0f);
    for (const RecordedPath& path : traced.paths) mean += path.summedContributions() / static_cast<float>(spp);
    const glm::vec3 rendered = session->tracer(ViewerSession::Side::Left).readMean().at(pixel.x, pixel.y);
    EXPECT_GT(rendered.r, 0.0f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], rendered[c], 1e-4f * (1.0f + rendered[c]));
    EXPECT_THROW(session->tracePaths({24, 0}, 4), std::invalid_argument);
    EXPECT_TRUE(session->tracedPaths().has_value()) << "a refused trace keeps the last paths";
}

// ---- the denoiser (docs/viewer.md, "Denoising") ---------------------------------------------

const ExrChannel* exrChannel(const ExrImage& exr, const std::string& name) {
    for (const ExrChannel& channel : exr.channels)
        if (channel.name == name) return &channel;
    return nullptr;
}

// The denoised image is a view of the accumulation: turning it on or off, changing its settings
// or splitting raw | denoised never starts the samples over.
TEST_F(ViewerSessionTest, TogglingDenoiseOrItsSettingsDoesNotRestartTheAccumulation) {
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    ViewerModel& model = session->model();
    renderSamples(*session, 3);
    const PathTracer& tracer = session->tracer(ViewerSession::Side::Left);
    const int restarts = tracer.restartCount();
    int samples = tracer.sampleCount();
    auto expectSameAccumulation = [&](const char* step) {
        session->update();
        EXPECT_EQ(tracer.restartCount(), restarts) << step;
        EXPECT_GE(tracer.sampleCount(), samples) << step;
        samples = tracer.sampleCount();
    };
    model.denoise.enabled = true;
    expectSameAccumulation("denoise on");
    EXPECT_TRUE(tracer.denoiseSettings().enabled);
    session->renderFrame();
    model.denoise.strength = 9.0f;
    model.denoise.iterations = 2;
    expectSameAccumulation("strength and iterations");
    EXPECT_FLOAT_EQ(tracer.denoiseSettings().strength, 9.0f);
    EXPECT_EQ(tracer.denoiseSettings().iterations, 2);
    model.compare.enabled = true;
    model.compare.sides = CompareSides::RawAndDenoised;
    expectSameAccumulation("raw | denoised split");
    EXPECT_TRUE(session->comparing());
    model.compare.enabled = false;
    model.denoise.enabled = false;
    expectSameAccumulation("denoise off");
    EXPECT_FALSE(tracer.denoiseSettings().enabled);
    renderSamples(*session, samples + 1);
    EXPECT_EQ(tracer.restartCount(), restarts);
}

// What the session displays with denoise on is the tracer's denoised image, tone mapped; once the
// samples stop, the last of them are denoised, in bands over as many frames as that takes.
TEST_F(ViewerSessionTest, TheDisplayShowsTheDenoisedImageOfTheLastSample) {
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    ViewerModel& model = session->model();
    model.targetSamples = 4;
    renderSamples(*session, 4);
    ASSERT_FALSE(session->accumulating());
    model.denoise.enabled = true;
    session->update();
    EXPECT_TRUE(session->denoisePending());
    renderUntilDenoised(*session);
    EXPECT_EQ(session->tracer(ViewerSession::Side::Left).sampleCount(), 4) << "no sample was traced meanwhile";
    const PathTracer& tracer = session->tracer(ViewerSession::Side::Left);
    ASSERT_TRUE(tracer.hasDenoised());
    EXPECT_EQ(tracer.denoisedSampleCount(), 4);

    const DisplaySettings shown = session->displaySettings(ViewerSession::Side::Left);
    EXPECT_TRUE(shown.denoised);
    DisplaySettings rawSettings = shown;
    rawSettings.denoised = false;
    const ImageRgba8 denoised = tracer.readToneMapped(shown);
    EXPECT_NE(denoised.rgba, tracer.readToneMapped(rawSettings).rgba) << "4 spp of the Cornell box: the filter changes it";
    // display() itself draws it (the image area is the render's size: one texel a pixel).
    ASSERT_EQ(session->displayArea().size, session->renderSize());
    const ImageRgba8 drawn = renderOffscreenRgba8(session->renderSize(), [&](glm::ivec2) { session->display(); });
    EXPECT_EQ(drawn.rgba, denoised.rgba);

    // The pixel inspector has the raw mean and the denoised value.
    model.pinnedPixel = glm::ivec2(5, 7);
    std::optional<PixelInspection> inspection = session->inspectPinnedPixel();
    ASSERT_TRUE(inspection && inspection->denoised);
    const ImageRgbF denoisedMean = tracer.readDenoised();
    EXPECT_EQ(*inspection->denoised, denoisedMean.at(5, 7));
    EXPECT_EQ(inspection->reading.mean, tracer.readMean().at(5, 7));
    EXPECT_EQ(inspection->denoisedSamples, 4);
    const std::string json = pixelInspectionJson(*inspection, model.scene);
    EXPECT_NE(json.find("\"denoised\""), std::string::npos) << json;
    EXPECT_NE(json.find("\"denoised_spp\": 4"), std::string::npos) << json;

    model.denoise.enabled = false;
    session->update();
    EXPECT_FALSE(session->displaySettings(ViewerSession::Side::Left).denoised);
    EXPECT_FALSE(session->inspectPinnedPixel()->denoised);
}

// F12 with denoise on: the PNG and PFM are the denoised image, the EXR has it as RGB and the raw
// mean as "raw.", and every file says the denoiser made it, so that opening it turns it on.
TEST_F(ViewerSessionTest, ScreenshotsWithDenoiseHoldTheDenoisedImageTheRawLayerAndTheSettings) {
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    ViewerModel& model = session->model();
    renderSamples(*session, 3);
    model.denoise = DenoiseSettings{true, 3, 6.0f};
    session->update(); // no renderFrame: the screenshot denoises what there is itself
    testing::ScratchFiles scratch("session_denoise");
    const fs::path& directory = scratch.directory();
    std::vector<fs::path> files = session->saveScreenshots(directory);
    ASSERT_EQ(files.size(), 3u);
    const PathTracer& tracer = session->tracer(ViewerSession::Side::Left);
    ASSERT_TRUE(tracer.denoisedUpToDate());
    const ImageRgbF denoised = tracer.readDenoised(), raw = tracer.readMean();
    EXPECT_EQ(readPfm(files[1]).rgb, denoised.rgb);
    ExrImage exr = readExr(files[2]);
    EXPECT_EQ(exrRgb(exr, files[2].string()).rgb, denoised.rgb);
    const ExrChannel* rawRed = exrChannel(exr, "raw.R");
    ASSERT_TRUE(rawRed && exrChannel(exr, "raw.G") && exrChannel(exr, "raw.B"));
    for (size_t i = 0; i < rawRed->values.size(); i += 37) EXPECT_EQ(rawRed->values[i], raw.rgb[3 * i]) << i;
    for (const fs::path& file : {files[0], files[2]}) {
        const RenderRecipe recipe = readProvenance(file).recipe;
        EXPECT_EQ(recipe.denoise, model.denoise) << file;
    }

    // Off: the raw image, and the files say so.
    model.denoise.enabled = false;
    session->update();
    files = session->saveScreenshots(directory);
    EXPECT_EQ(readPfm(files[1]).rgb, raw.rgb);
    EXPECT_EQ(exrChannel(readExr(files[2]), "raw.R"), nullptr);
    EXPECT_FALSE(readProvenance(files[0]).recipe.denoise.enabled);
}

// The split view compares raw and denoised of one render (no second tracer, both halves the same
// samples), or two renders, each denoised where its own setting says.
TEST_F(ViewerSessionTest, SplitViewShowsRawAndDenoisedOfOneRenderOrEachRendersOwnChoice) {
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    ViewerModel& model = session->model();
    model.compare.enabled = true;
    model.compare.sides = CompareSides::RawAndDenoised;
    renderSamples(*session, 2);
    ASSERT_TRUE(session->comparing());
    EXPECT_FALSE(session->comparesTwoRenders());
    EXPECT_EQ(&session->tracer(ViewerSession::Side::Right), &session->tracer(ViewerSession::Side::Left));
    EXPECT_TRUE(session->accumulating()) << "the one render's, with no second tracer to ask";
    session->model().pinnedPixel = glm::ivec2(20, 3); // right of the divider: the denoised side
    while (!session->tracer(ViewerSession::Side::Left).hasDenoised()) session->renderFrame();
    std::optional<PixelInspection> right = session->inspectPinnedPixel();
    ASSERT_TRUE(right);
    EXPECT_TRUE(right->rightSide);
    EXPECT_TRUE(right->denoised);
    EXPECT_FALSE(session->displaySettings(ViewerSession::Side::Left).denoised);
    EXPECT_TRUE(session->displaySettings(ViewerSession::Side::Right).denoised);
    testing::ScratchFiles scratch("session_split_denoise");
    const fs::path& directory = scratch.directory();
    std::vector<fs::path> files = session->saveScreenshots(directory);
    ASSERT_EQ(files.size(), 6u);
    const PathTracer& tracer = session->tracer(ViewerSession::Side::Left);
    EXPECT_EQ(readPfm(files[1]).rgb, tracer.readMean().rgb);     // left: raw
    EXPECT_EQ(readPfm(files[4]).rgb, tracer.readDenoised().rgb); // right: denoised
    EXPECT_FALSE(readProvenance(files[0]).recipe.denoise.enabled);
    EXPECT_TRUE(readProvenance(files[3]).recipe.denoise.enabled);

    model.compare.sides = CompareSides::TwoRenders;
    model.compare.rightDenoised = true;
    model.compare.right.integrator = Integrator::Mis;
    renderSamples(*session, 2);
    ASSERT_TRUE(session->comparesTwoRenders());
    EXPECT_NE(&session->tracer(ViewerSession::Side::Right), &session->tracer(ViewerSession::Side::Left));
    EXPECT_FALSE(session->displaySettings(ViewerSession::Side::Left).denoised);
    EXPECT_TRUE(session->displaySettings(ViewerSession::Side::Right).denoised);
    EXPECT_FALSE(session->tracer(ViewerSession::Side::Left).denoiseSettings().enabled);
    EXPECT_TRUE(session->tracer(ViewerSession::Side::Right).denoiseSettings().enabled);
    model.denoise.enabled = true;
    session->update();
    EXPECT_TRUE(session->displaySettings(ViewerSession::Side::Left).denoised);
}

// The difference views' image: a file that cannot be read, or of another size than the render,
// says why in the viewer (sceneError) and keeps the image before; none goes back to the reference.
TEST_F(ViewerSessionTest, ABadOrMismatchedCompareImageSaysWhyAndKeepsTheOneBefore) {
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    renderSamples(*session, 1);
    ASSERT_EQ(session->renderSize(), glm::ivec2(24, 24));
    testing::ScratchFiles files("session_compare");
    ImageRgbF image(24, 24);
    image.rgb.assign(image.rgb.size(), 0.25f);
    const fs::path good = files.write("good.pfm", "");
    writePfm(good, image);
    ViewerModel& model = session->model();
    model.display.view = DisplayView::Difference;
    EXPECT_NE(session->viewProblem(ViewerSession::Side::Left), "") << "no image to compare with yet";
    ASSERT_TRUE(session->setCompareImage(good)) << model.sceneError;
    EXPECT_EQ(session->viewProblem(ViewerSession::Side::Left), "");
    const std::shared_ptr<const ImageRgbF> loaded = model.compareImage;

    const fs::path small = files.write("small.pfm", "");
    writePfm(small, ImageRgbF(16, 12));
    EXPECT_FALSE(session->setCompareImage(small));
    EXPECT_NE(model.sceneError.find(small.string() + " is 16x12 but the render is 24x24"), std::string::npos) << model.sceneError;
    const fs::path garbage = files.write("garbage.pfm", "PF\nnot a size\n");
    EXPECT_FALSE(session->setCompareImage(garbage));
    EXPECT_NE(model.sceneError.find(garbage.string()), std::string::npos) << model.sceneError;
    EXPECT_FALSE(session->setCompareImage(files.directory() / "missing.exr"));
    EXPECT_EQ(model.compareImage, loaded) << "the image before is kept";
    EXPECT_EQ(model.compareImagePath, good);
    session->update();
    EXPECT_EQ(session->tracer(ViewerSession::Side::Left).otherImage(), loaded);

    ASSERT_TRUE(session->setCompareImage({}));
    EXPECT_FALSE(model.compareImage);
    ASSERT_TRUE(session->setReference(good));
    EXPECT_EQ(session->otherImageFor(DisplayView::Difference), model.reference) << "without one, the reference";
    EXPECT_EQ(session->otherImageFor(DisplayView::Error), model.reference);
}

// Zoomed and panned, the session draws render pixel p at exactly the framebuffer pixels whose
// centres pixelAtFramebuffer names p: the pin of a click is the pixel the user sees.
TEST_F(ViewerSessionTest, ZoomedPixelAtFramebufferIsThePixelDrawnThere) {
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    session->setImageArea(PixelRect{{0, 0}, {40, 20}});
    session->model().pendingChanges |= ViewerModel::kRestart;
    renderSamples(*session, 2);
    ASSERT_EQ(session->renderSize(), glm::ivec2(40, 20));
    // Shown scaled (it has samples), fitted with bars: 3/5 of a render pixel a screen pixel, so no
    // screen pixel's centre falls on an edge between render pixels.
    session->setImageArea(PixelRect{{0, 0}, {24, 24}});
    session->update();
    const ImageRgba8 whole = session->tracer(ViewerSession::Side::Left).readToneMapped(session->displaySettings(ViewerSession::Side::Left));
    for (auto [scale, pan] : {std::pair{0.0f, glm::vec2(0.0f)}, std::pair{1.0f, glm::vec2(3.0f, -2.0f)},
                              std::pair{4.0f, glm::vec2(5.0f, 3.0f)}}) {
        SCOPED_TRACE(::testing::Message() << "scale " << scale);
        session->fitImage();
        if (scale > 0.0f) session->zoomImageTo(scale, glm::vec2(7.0f, 9.0f));
        if (pan != glm::vec2(0.0f)) session->panImage(pan);
        ImageRgba8 shown = renderOffscreenRgba8(glm::ivec2(24, 24), [&](glm::ivec2) { session->display(); });
        int drawn = 0;
        for (int y = 0; y < 24; ++y)
            for (int x = 0; x < 24; ++x) {
                std::optional<glm::ivec2> pixel = session->pixelAtFramebuffer(glm::vec2(x, y) + 0.5f);
                if (!pixel) continue;
                ++drawn;
                size_t at = (static_cast<size_t>(23 - y) * 24 + x) * 4; // rows top first
                size_t expected = (static_cast<size_t>(pixel->y) * 40 + pixel->x) * 4;
                ASSERT_EQ(glm::ivec3(shown.rgba[at], shown.rgba[at + 1], shown.rgba[at + 2]),
                          glm::ivec3(whole.rgba[expected], whole.rgba[expected + 1], whole.rgba[expected + 2]))
                    << "framebuffer " << x << " " << y << " render " << pixel->x << " " << pixel->y;
            }
        EXPECT_GT(drawn, 24 * 10);
    }
}

// ---- undo and redo (EditHistory.h; the window calls recordEdits every frame, scripts after every command)

const Material& named(const std::vector<Material>& materials, const std::string& name) {
    for (const Material& m : materials)
        if (m.name == name) return m;
    throw std::runtime_error("no material " + name);
}

Material& editable(ViewerSession& session, const std::string& name) {
    for (Material& m : session.model().scene.materials)
        if (m.name == name) return m;
    throw std::runtime_error("no material " + name);
}

// An undo restores the scene's value and flags only what changed for the renderer, which starts
// the image again; a redo does the same the other way; nothing to undo says so and changes nothing.
TEST_F(ViewerSessionTest, UndoAndRedoRestoreAnEditAndRestartTheRenderForWhatChangedOnly) {
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    ViewerModel& model = session->model();
    const glm::vec3 fileColor = material(*session, "white").color;
    EXPECT_FALSE(session->undo());
    EXPECT_EQ(model.notice, "nothing to undo");
    EXPECT_EQ(model.pendingChanges, 0u);

    editable(*session, "white").color = glm::vec3(0.2f, 0.7f, 0.2f);
    model.pendingChanges |= ViewerModel::kMaterialsChanged;
    session->recordEdits();
    EXPECT_EQ(session->history().undoLabel(), "albedo of 'white'");
    renderSamples(*session, 2);

    ASSERT_TRUE(session->undo());
    EXPECT_EQ(model.notice, "undid albedo of 'white'");
    EXPECT_EQ(material(*session, "white").color, fileColor);
    EXPECT_EQ(model.pendingChanges, unsigned(ViewerModel::kMaterialsChanged)) << "a material: no scene upload, no camera";
    session->update();
    EXPECT_EQ(session->stats(ViewerSession::Side::Left).samples, 0) << "the render starts again";
    renderSamples(*session, 1);

    ASSERT_TRUE(session->redo());
    EXPECT_EQ(model.notice, "redid albedo of 'white'");
    EXPECT_EQ(material(*session, "white").color, glm::vec3(0.2f, 0.7f, 0.2f));
    EXPECT_EQ(model.pendingChanges, unsigned(ViewerModel::kMaterialsChanged));
    session->update();
    EXPECT_EQ(session->stats(ViewerSession::Side::Left).samples, 0);
    EXPECT_FALSE(session->redo());
    EXPECT_EQ(model.notice, "nothing to redo");

    const CameraDesc camera = model.scene.camera;
    model.scene.camera.eye.x += 0.5f; // an orbit, a pan, a key
    model.pendingChanges |= ViewerModel::kCameraChanged;
    session->update();
    ASSERT_TRUE(session->undo()); // recorded first: the edit not yet recorded is the one undone
    EXPECT_EQ(model.scene.camera.eye, camera.eye);
    EXPECT_EQ(model.pendingChanges, unsigned(ViewerModel::kCameraChanged));
    EXPECT_EQ(session->history().redoLabel(), "camera");

    // An emitter's radiance is a material parameter too; a new edit drops the camera's redo.
    session->update();
    editable(*session, "light").radiance = glm::vec3(1.0f);
    ASSERT_TRUE(session->undo());
    EXPECT_EQ(model.pendingChanges, unsigned(ViewerModel::kMaterialsChanged));
    EXPECT_EQ(session->history().redoLabel(), "radiance of 'light'");
    EXPECT_EQ(session->history().redoSteps(), 1u);
}

// An environment map chosen and then undone: the map goes, with a scene upload; redone, it is
// the map decoded before, not read again.
TEST_F(ViewerSessionTest, UndoingAnEnvironmentMapChoiceKeepsItsDecodedMapForRedo) {
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    ViewerModel& model = session->model();
    const fs::path hdr = fs::path(PTVIEW_ASSETS_DIR) / "hdr/studio_small_03_1k.hdr";
    ASSERT_TRUE(session->setEnvironmentMap(hdr));
    session->recordEdits();
    const std::shared_ptr<const EnvironmentMap> map = model.environmentMap;
    ASSERT_TRUE(map);
    model.scene.environmentIntensity = 2.5f;
    model.pendingChanges |= ViewerModel::kSceneChanged;
    session->recordEdits();
    session->update();
    EXPECT_EQ(session->history().undoLabel(), "environment intensity");

    ASSERT_TRUE(session->undo());
    EXPECT_EQ(model.scene.environmentIntensity, 1.0f);
    EXPECT_EQ(model.environmentMap, map);
    session->update();
    ASSERT_TRUE(session->undo());
    EXPECT_EQ(model.notice, "undid environment map");
    EXPECT_TRUE(model.scene.environmentMap.empty());
    EXPECT_EQ(model.environmentMap, nullptr);
    EXPECT_EQ(model.pendingChanges, unsigned(ViewerModel::kSceneChanged));
    session->update();
    ASSERT_TRUE(session->redo());
    EXPECT_EQ(model.scene.environmentMap, hdr);
    EXPECT_EQ(model.environmentMap, map) << "the same decoded map";
    session->update();
    EXPECT_EQ(model.sceneError, "");
}

// A texture given to a material (the Materials panel's Load, the script's -texture field) is a
// step: undone, the material has no texture again and the scene is uploaded again.
TEST_F(ViewerSessionTest, UndoTakesBackATextureAssignment) {
    testing::ScratchFiles files("undo_texture");
    const fs::path png = files.write("t.png", "");
    writePng(png, ImageRgba8{1, 1, {10, 20, 200, 255}});
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    ViewerModel& model = session->model();
    const std::size_t textures = model.scene.textures.size();
    Material& white = editable(*session, "white");
    white.type = MaterialType::Principled; // as the panel's type combo does first
    session->recordEdits();
    setMaterialTexture(model.scene, white, kMaterialTextureInputs[0], png);
    model.pendingChanges |= ViewerModel::kSceneChanged;
    session->recordEdits();
    session->update();
    EXPECT_EQ(session->history().undoLabel(), "base color texture of 'white'");

    ASSERT_TRUE(session->undo());
    EXPECT_FALSE(material(*session, "white").baseColorTexture.used());
    EXPECT_EQ(material(*session, "white").type, MaterialType::Principled);
    EXPECT_EQ(model.scene.textures.size(), textures);
    EXPECT_EQ(model.pendingChanges, unsigned(ViewerModel::kSceneChanged));
    session->update();
    ASSERT_TRUE(session->redo());
    ASSERT_TRUE(material(*session, "white").baseColorTexture.used());
    EXPECT_EQ(model.scene.textures.back().file, png);
    session->update();
    renderSamples(*session, 1);
}

// The issue's rule: the history never holds a state the scene format would refuse, and an undo
// after a failed reload restores the last good scene with the edits before the undone one kept.
// A good reload then rebases the history: undo walks the user's edits on top of the new file.
TEST_F(ViewerSessionTest, UndoAfterAFailedReloadRestoresTheLastGoodSceneWithItsEditsKept) {
    testing::ScratchFiles scratch("session_undo_reload");
    const fs::path& directory = scratch.directory();
    fs::path scenePath = directory / "cornell.json";
    const std::string original = testing::readFileBytes(PTVIEW_ASSETS_DIR "/scenes/cornell.json");
    writeText(scenePath, original);
    auto session = openSession(scenePath);
    ViewerModel& model = session->model();
    const Scene file = model.fileScene;
    editable(*session, "white").color = glm::vec3(0.2f, 0.7f, 0.2f);
    session->recordEdits();
    editable(*session, "red").color = glm::vec3(0.1f, 0.1f, 0.9f);
    session->recordEdits();
    session->update();

    waitForWatcher();
    writeText(scenePath, original.substr(0, original.size() / 2));
    session->pollFiles();
    ASSERT_NE(model.sceneError, "");
    ASSERT_TRUE(session->undo());
    EXPECT_EQ(material(*session, "red").color, named(file.materials, "red").color) << "the last edit undone";
    EXPECT_EQ(material(*session, "white").color, glm::vec3(0.2f, 0.7f, 0.2f)) << "the one before kept";
    EXPECT_EQ(model.scene.shapes.size(), file.shapes.size()) << "the last good scene";
    EXPECT_TRUE(sameEdits(session->history().current(), model.scene));
    session->update();
    renderSamples(*session, 1);

    // A state no file could hold is never recorded: the eye beyond the format's 1e9 m. Undo takes it back.
    model.scene.camera.eye.x = 2e9f;
    session->recordEdits();
    EXPECT_NE(session->history().refused().find("camera"), std::string::npos) << session->history().refused();
    EXPECT_EQ(session->history().undoSteps(), 1u);
    ASSERT_TRUE(session->undo());
    EXPECT_EQ(model.scene.camera.eye, file.camera.eye);
    EXPECT_EQ(material(*session, "white").color, glm::vec3(0.2f, 0.7f, 0.2f)) << "only the refused edit went";
    EXPECT_EQ(session->history().undoSteps(), 1u);
    session->update();

    // The file fixed, with a brighter light: the reload keeps the edit, and undo goes back to the new file.
    ASSERT_TRUE(session->redo()) << "the red wall again";
    waitForWatcher();
    writeText(scenePath, replaced(original, "[17.0, 12.0, 4.0]", "[34.0, 24.0, 8.0]"));
    session->pollFiles();
    ASSERT_EQ(model.sceneError, "");
    EXPECT_EQ(session->history().undoSteps(), 2u);
    EXPECT_EQ(session->history().undoLabel(), "albedo of 'red'");
    ASSERT_TRUE(session->undo());
    ASSERT_TRUE(session->undo());
    EXPECT_EQ(material(*session, "white").color, named(file.materials, "white").color);
    EXPECT_EQ(material(*session, "light").radiance, glm::vec3(34.0f, 24.0f, 8.0f)) << "the file's change stays";
    EXPECT_FALSE(session->hasUnsavedEdits()) << "back to the file as it is now";
}

// Save moves the "saved" mark, not the history: the title's star follows undo and redo back to
// the saved state. Reload with the edits discarded is a step undo takes back; opening another
// scene starts afresh.
TEST_F(ViewerSessionTest, SaveKeepsTheHistoryAndTheStarFollowsUndoBackToTheSavedState) {
    testing::ScratchFiles scratch("session_undo_save");
    const fs::path& directory = scratch.directory();
    auto session = openSession(fs::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json");
    const glm::vec3 fileColor = material(*session, "white").color;
    editable(*session, "white").color = glm::vec3(0.2f, 0.7f, 0.2f);
    session->recordEdits();
    EXPECT_TRUE(session->hasUnsavedEdits());
    session->saveSceneAs(directory / "mine.json");
    EXPECT_FALSE(session->hasUnsavedEdits());
    EXPECT_EQ(session->history().undoSteps(), 1u) << "Save keeps the history";
    ASSERT_TRUE(session->undo());
    EXPECT_TRUE(session->hasUnsavedEdits()) << "the saved file has the edit";
    ASSERT_TRUE(session->redo());
    EXPECT_FALSE(session->hasUnsavedEdits()) << "the saved state again: no star";

    // Reload, discarding an edit: undoable.
    editable(*session, "white").color = glm::vec3(0.9f, 0.1f, 0.1f);
    UnsavedEditsPrompt prompt;
    prompt.request(*session, UnsavedEditsPrompt::Action::Reload);
    prompt.answer(*session, UnsavedEditsPrompt::Answer::Discard);
    EXPECT_EQ(material(*session, "white").color, glm::vec3(0.2f, 0.7f, 0.2f)) << "the saved file as it is";
    EXPECT_NE(session->history().undoLabel().find("discarding the edits"), std::string::npos) << session->history().undoLabel();
    ASSERT_TRUE(session->undo());
    EXPECT_EQ(material(*session, "white").color, glm::vec3(0.9f, 0.1f, 0.1f)) << "the discarded edit back";
    ASSERT_TRUE(session->undo());
    ASSERT_TRUE(session->undo());
    EXPECT_EQ(material(*session, "white").color, fileColor);

    ASSERT_TRUE(session->openScene(fs::path(PTVIEW_ASSETS_DIR) / "scenes/materials.json"));
    EXPECT_FALSE(session->history().canUndo());
    EXPECT_FALSE(session->history().canRedo());
    EXPECT_FALSE(session->undo());
}

} // namespace
} // namespace ptview
