// The script executor's dispatch table against the parser's command table: a command that parses
// always has a handler, and no handler waits for a command the parser would refuse.
#include "GlTestContext.h"
#include <ptview/io/ImageIO.h>
#include <ptview/window/MaterialsPanel.h>
#include <ptview/model/SceneInput.h>
#include <ptview/scene/MaterialSchema.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/scene/SceneWriter.h>
#include <ptview/window/ScriptRunner.h>
#include "TestFiles.h"
#include <ptview/model/ViewerScript.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

namespace ptview {
namespace {

TEST(ScriptRunner, EveryCommandOfTheScriptTableHasAHandler) {
    std::vector<std::string> table = viewerScriptVerbs();
    std::vector<std::string> handled = ScriptRunner::handledVerbs();
    ASSERT_FALSE(table.empty());
    for (const std::string& verb : table)
        EXPECT_EQ(std::count(handled.begin(), handled.end(), verb), 1) << "\"" << verb << "\": handlers for it";
    for (const std::string& verb : handled)
        EXPECT_NE(std::find(table.begin(), table.end(), verb), table.end())
            << "a handler for \"" << verb << "\", which the script table does not have";
}

// Runs the script on a headless session of the scene until it ends (no command here waits).
struct ScriptedSession {
    std::unique_ptr<ViewerSession> session;
    ScriptRunner runner;
    PanelState panels;

    ScriptedSession(const std::filesystem::path& scene, const std::string& script)
        : runner(parseViewerScript(script, "s.txt")) {
        testing::glContext();
        std::optional<SceneInput> input = loadSceneInput(scene.string());
        EXPECT_TRUE(input);
        session = std::make_unique<ViewerSession>(std::move(*input), testing::naiveSettings(2, 0), DisplaySettings{},
                                                  PTVIEW_SHADER_DIR);
        session->setImageArea(PixelRect{{0, 0}, {8, 8}});
        runner.step(*session, panels);
        session->update();
    }
    const Material& material(const std::string& name) const {
        for (const Material& m : session->model().scene.materials)
            if (m.name == name) return m;
        throw std::runtime_error("no material " + name);
    }
};

// The Materials panel's edits by script: principled factors live, a texture removed (none) or
// given from a file (a diffuse material becoming principled, keeping its colour), the slot then
// naming a new scene texture in the input's colour space.
// The panel's and the script's type change keeps a glTF file's material the file's, so that Save
// writes it as an override of it (it became a material of the scene's own, of the same name as the
// one the glTF file makes again on loading).
TEST(ScriptRunner, ATypeChangeOfAGltfMaterialIsSavedAsAnOverride) {
    testing::ScratchFiles files("retype");
    files.write("tiny.gltf", R"({"asset": {"version": "2.0"}, "materials": [{"name": "red", "pbrMetallicRoughness": {"roughnessFactor": 0.25}}]})");
    Scene scene = loadScene(files.write("scene.json", R"({"camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "vfov_deg": 40,
        "resolution": [8, 8]}, "materials": {}, "shapes": [], "gltf": [{"file": "tiny.gltf"}]})"));
    ASSERT_EQ(scene.materials.size(), 1u);
    scene.materials[0] = retypedMaterial(scene.materials[0], MaterialType::Plastic);
    EXPECT_EQ(scene.materials[0].importedFrom, 0);
    const std::string written = sceneToJson(scene);
    EXPECT_NE(written.find(R"("materials": {"tiny/red": {"type": "plastic"})"), std::string::npos) << written;
    EXPECT_NE(written.find(R"("materials": {},)"), std::string::npos) << written;
}

TEST(ScriptRunner, SetMaterialEditsPrincipledFactorsAndTextures) {
    testing::ScratchFiles files("script");
    const std::filesystem::path png = files.write("t.png", "");
    writePng(png, ImageRgba8{2, 1, {10, 20, 30, 255, 40, 50, 60, 255}});
    ScriptedSession run(PTVIEW_ASSETS_DIR "/scenes/cornell_spot.json",
                        "set-material spot/spot.metallic 0.5\nset-material spot/spot.normal-scale 0.25\n"
                        "set-material spot/spot.alpha 0.75\nset-material spot/spot.transmission 0.125\n"
                        "set-material spot/spot.base-color-texture none\n"
                        "set-material white.base-color-texture " + png.string() + "\n"
                        "set-material white.normal-texture " + png.string() + "\n");
    EXPECT_EQ(run.runner.exitCode(), 0);
    const Material& spot = run.material("spot/spot");
    EXPECT_FLOAT_EQ(spot.metallic, 0.5f);
    EXPECT_FLOAT_EQ(spot.normalScale, 0.25f);
    EXPECT_FLOAT_EQ(spot.alpha, 0.75f);
    EXPECT_FLOAT_EQ(spot.transmission, 0.125f);
    EXPECT_FALSE(spot.baseColorTexture.used());
    const Material& white = run.material("white");
    EXPECT_EQ(white.type, MaterialType::Principled);
    EXPECT_EQ(white.color, glm::vec3(0.73f));
    ASSERT_TRUE(white.baseColorTexture.used() && white.normalTexture.used());
    const std::vector<SceneTexture>& textures = run.session->model().scene.textures;
    const SceneTexture& base = textures.at(static_cast<std::size_t>(white.baseColorTexture.texture));
    EXPECT_EQ(base.file, png);
    EXPECT_EQ(base.colorSpace, TextureColorSpace::Srgb);
    EXPECT_EQ(textures.at(static_cast<std::size_t>(white.normalTexture.texture)).colorSpace, TextureColorSpace::Linear);
    ASSERT_TRUE(base.image);
    EXPECT_EQ(base.image->rgba, (std::vector<std::uint8_t>{10, 20, 30, 255, 40, 50, 60, 255}));
}

// The Render panel's OpenColorIO controls by script: a config's default view, then another view;
// a view the display lacks ends the script (exit code 2) and the view shown stays.
TEST(ScriptRunner, OcioCommandsPickAConfigsViewsAndABadOneKeepsTheViewShown) {
    const std::string config = PTVIEW_TEST_DATA_DIR "/ocio/config.ocio";
    ScriptedSession run(PTVIEW_ASSETS_DIR "/scenes/cornell.json", "ocio-config " + config + "\nocio-view matrix\n");
    EXPECT_EQ(run.runner.exitCode(), 0);
    const ViewerModel& model = run.session->model();
    EXPECT_EQ(model.display.toneMapper, ToneMapper::Ocio);
    EXPECT_EQ(model.ocio.config, config);
    EXPECT_EQ(model.ocio.display, "test");
    EXPECT_EQ(model.ocio.view, "matrix");
    ASSERT_EQ(run.session->ocioDisplays().size(), 1u);
    EXPECT_EQ(run.session->ocioDisplays()[0].views.size(), 3u);
    ASSERT_NE(run.session->tracer(ViewerSession::Side::Left).ocioView(), nullptr);
    EXPECT_EQ(run.session->tracer(ViewerSession::Side::Left).ocioView()->view(), "matrix");

    ScriptedSession bad(PTVIEW_ASSETS_DIR "/scenes/cornell.json", "ocio-config " + config + "\nocio-view Filmic\n");
    EXPECT_EQ(bad.runner.exitCode(), 2);
    EXPECT_NE(bad.session->model().ocioError.find("has no view \"Filmic\""), std::string::npos) << bad.session->model().ocioError;
    EXPECT_EQ(bad.session->model().ocio.view, "square root") << "the view shown stays";
    EXPECT_EQ(bad.session->tracer(ViewerSession::Side::Left).ocioView()->view(), "square root");

    ScriptedSession missing(PTVIEW_ASSETS_DIR "/scenes/cornell.json", "ocio-config /nonexistent/config.ocio\n");
    EXPECT_EQ(missing.runner.exitCode(), 2);
    EXPECT_NE(missing.session->model().ocioError.find("/nonexistent/config.ocio: "), std::string::npos);
    EXPECT_EQ(missing.session->model().display.toneMapper, ToneMapper::Reinhard) << "the transform shown stays";
}

// A texture file that does not load ends the script naming the file (exit code 2, as every failing
// command), and the material keeps the texture it had.
TEST(ScriptRunner, ATextureThatDoesNotLoadFailsNamingItAndKeepsTheMaterial) {
    testing::ScratchFiles files("script");
    const std::filesystem::path bad = files.write("bad.png", "not an image");
    ScriptedSession run(PTVIEW_ASSETS_DIR "/scenes/cornell_spot.json",
                        "set-material spot/spot.base-color-texture " + bad.string() + "\n");
    EXPECT_EQ(run.runner.exitCode(), 2);
    const Material& spot = run.material("spot/spot");
    ASSERT_TRUE(spot.baseColorTexture.used());
    EXPECT_NE(run.session->model().scene.textures.at(static_cast<std::size_t>(spot.baseColorTexture.texture)).source.find("spot_texture.png"),
              std::string::npos);
}

// The denoiser's commands edit the model as the Render panel's controls do, and restart nothing.
TEST(ScriptRunner, DenoiseCommandsSetTheModelsDenoiserAndSplit) {
    ScriptedSession scripted(std::filesystem::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json",
                             "denoise on\ndenoise-strength 8\ndenoise-iterations 3\ncompare-sides raw-denoised\n"
                             "compare-denoise on\ndenoise-algorithm regression\n");
    const ViewerModel& model = scripted.session->model();
    EXPECT_TRUE(model.denoise.enabled);
    EXPECT_FLOAT_EQ(model.denoise.strength, 8.0f);
    EXPECT_EQ(model.denoise.iterations, 3);
    EXPECT_EQ(model.denoise.algorithm, DenoiseAlgorithm::Regression);
    EXPECT_EQ(model.compare.sides, CompareSides::RawAndDenoised);
    EXPECT_TRUE(model.compare.rightDenoised);
    const DenoiseSettings& pushed = scripted.session->tracer(ViewerSession::Side::Left).denoiseSettings();
    EXPECT_TRUE(pushed.enabled);
    EXPECT_FLOAT_EQ(pushed.strength, 8.0f);
    EXPECT_EQ(pushed.iterations, 3);
    EXPECT_EQ(pushed.algorithm, DenoiseAlgorithm::Regression);
}

// `target-error E` turns adaptive sampling of the main view on at E, `target-error off` turns it
// off; each change restarts the accumulation (ViewerSession::syncAdaptive).
TEST(ScriptRunner, TargetErrorTurnsAdaptiveSamplingOnAndOff) {
    ScriptedSession scripted(std::filesystem::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json", "target-error 0.03\n");
    ViewerSession& session = *scripted.session;
    EXPECT_TRUE(session.model().targetErrorOn);
    EXPECT_FLOAT_EQ(session.model().targetError, 0.03f);
    ViewerSession::ViewStats stats = session.stats(ViewerSession::Side::Left);
    ASSERT_TRUE(stats.adaptive);
    EXPECT_NEAR(stats.adaptive->targetError, 0.03, 1e-6);

    ScriptedSession off(std::filesystem::path(PTVIEW_ASSETS_DIR) / "scenes/cornell.json", "target-error 0.03\ntarget-error off\n");
    EXPECT_FALSE(off.session->model().targetErrorOn);
    EXPECT_FLOAT_EQ(off.session->model().targetError, 0.03f) << "kept for the Render panel's checkbox";
    EXPECT_FALSE(off.session->stats(ViewerSession::Side::Left).adaptive);
}

// `undo` and `redo` by script: each command's edit is one step; undo restores the value and the
// render starts again for what changed (a material alone: no scene upload); redo brings it back.
TEST(ScriptRunner, UndoAndRedoWalkTheScriptsEditsOneCommandAtATime) {
    const std::filesystem::path cornell = PTVIEW_ASSETS_DIR "/scenes/cornell.json";
    const Scene file = loadScene(cornell);
    ScriptedSession run(cornell, "set-material red.color 0.1 0.1 0.9\ncamera-orbit 10 0\nenvironment-color 0.2 0.2 0.2\n");
    ASSERT_EQ(run.runner.exitCode(), 0);
    ViewerSession& session = *run.session;
    EXPECT_EQ(session.history().undoSteps(), 3u);
    EXPECT_EQ(session.history().undoLabel(), "environment colour");
    while (session.stats(ViewerSession::Side::Left).samples < 1) session.renderFrame();

    auto runScript = [&](const std::string& text) {
        ScriptRunner runner(parseViewerScript(text, "u.txt"));
        runner.step(session, run.panels);
        return runner.exitCode();
    };
    EXPECT_EQ(runScript("undo\nundo\n"), 0);
    EXPECT_EQ(run.panels.imageNotice, "undid camera");
    EXPECT_EQ(session.model().scene.camera.eye, file.camera.eye);
    EXPECT_EQ(session.model().scene.environment, file.environment);
    EXPECT_EQ(session.model().pendingChanges, unsigned(ViewerModel::kSceneChanged | ViewerModel::kCameraChanged));
    session.update();
    EXPECT_EQ(session.stats(ViewerSession::Side::Left).samples, 0) << "the render restarted";
    while (session.stats(ViewerSession::Side::Left).samples < 1) session.renderFrame();

    EXPECT_EQ(runScript("undo\n"), 0);
    EXPECT_EQ(run.panels.imageNotice, "undid albedo of 'red'");
    EXPECT_EQ(run.material("red").color, glm::vec3(0.63f, 0.065f, 0.05f)) << "the file's";
    EXPECT_EQ(session.model().pendingChanges, unsigned(ViewerModel::kMaterialsChanged)) << "materials only";
    session.update();
    EXPECT_EQ(session.stats(ViewerSession::Side::Left).samples, 0);

    EXPECT_EQ(runScript("redo\n"), 0);
    EXPECT_EQ(run.material("red").color, glm::vec3(0.1f, 0.1f, 0.9f));
    EXPECT_EQ(run.panels.imageNotice, "redid albedo of 'red'");
    // A new edit drops what was left to redo.
    EXPECT_EQ(runScript("set-material white.color 0.5 0.5 0.5\n"), 0);
    EXPECT_FALSE(session.history().canRedo());
    EXPECT_EQ(session.history().undoSteps(), 2u);
}

// Nothing to undo or redo is a clear failure of the command (exit code 2, as any command that
// cannot be carried out), not a crash; the scene stays as it was.
TEST(ScriptRunner, UndoWithNothingToUndoFailsWithAMessage) {
    ScriptedSession undo(PTVIEW_ASSETS_DIR "/scenes/cornell.json", "undo\nset-material red.color 0 0 1\n");
    EXPECT_EQ(undo.runner.exitCode(), 2);
    EXPECT_EQ(undo.panels.imageNotice, "nothing to undo");
    EXPECT_EQ(undo.material("red").color, glm::vec3(0.63f, 0.065f, 0.05f)) << "the script ended at the undo";
    ScriptedSession redo(PTVIEW_ASSETS_DIR "/scenes/cornell.json", "set-material red.color 0 0 1\nredo\n");
    EXPECT_EQ(redo.runner.exitCode(), 2);
    EXPECT_EQ(redo.panels.imageNotice, "nothing to redo");
    EXPECT_EQ(redo.material("red").color, glm::vec3(0.0f, 0.0f, 1.0f));
}

// ---- Media (issue 38)

// A floor, a box of fog and a glass ball with a clear interior (docs/scene-format.md).
std::filesystem::path writeMediaScene(const testing::ScratchFiles& files) {
    return files.write("media.json", R"({"camera": {"eye": [0, 1, 4], "target": [0, 1, 0], "vfov_deg": 40, "resolution": [8, 8]},
  "materials": {
    "floor": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]},
    "fog": {"type": "medium", "sigma_a": [0.05, 0.05, 0.05], "sigma_s": [0.6, 0.6, 0.6], "g": 0.3},
    "ball": {"type": "glass", "ior": 1.5, "interior": {}},
    "pane": {"type": "glass"}
  },
  "shapes": [
    {"name": "ground", "type": "quad", "center": [0, 0, 0], "u": [2, 0, 0], "v": [0, 0, -2], "material": "floor"},
    {"type": "box", "center": [0, 1, 0], "half_size": [1, 1, 1], "material": "fog"},
    {"type": "sphere", "center": [0, 1, 0], "radius": 0.5, "material": "ball"},
    {"name": "window", "type": "quad", "center": [0, 1, -1.5], "u": [1, 0, 0], "v": [0, 1, 0], "material": "pane"}
  ]})");
}

// The panel's type combo and interior checkbox make materials that save and read back as they
// are: a medium has no colour or emission to lose, and a medium carries over into an interior.
TEST(ScriptRunner, TypeChangesToAndFromMediaSaveAndReadBackTheSame) {
    Scene scene = parseScene(R"({"camera": {"eye": [0, 0, 4], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [8, 8]},
        "materials": {"fog": {"type": "medium", "sigma_a": [0.5, 0.25, 1], "sigma_s": [2, 2, 2], "g": 0.5},
                      "amber": {"type": "glass", "tint": [0.9, 0.8, 0.7], "interior": {"sigma_a": [0.2, 2, 4]}},
                      "wall": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5], "emission": [1, 1, 1]}},
        "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "fog"}]})", "s.json");
    const std::vector<Material> originals = scene.materials;
    for (const Material& original : originals)
        for (const MaterialSchema& to : kMaterialSchemas) {
            SCOPED_TRACE(original.name + " as " + to.name);
            Material retyped = retypedMaterial(original, to.type);
            if (to.type != MaterialType::Emitter && (to.type == MaterialType::Medium || original.type == MaterialType::Medium)) {
                EXPECT_EQ(retyped.radiance, glm::vec3(0.0f)) << "no emission into or out of a medium";
            }
            for (bool holds : {false, true}) {
                const bool refracts = to.type == MaterialType::SpecularTransmission || to.type == MaterialType::Glass ||
                                      to.type == MaterialType::Principled;
                Material edited = refracts ? withInterior(retyped, holds) : retyped;
                edited.name = "edited"; // in the place of the sphere's, beside the originals
                scene.materials[0] = edited;
                const Scene again = parseScene(sceneToJson(scene), "again.json");
                EXPECT_TRUE(sameMaterial(again.materials[0], edited)) << sceneToJson(scene);
            }
        }
    const Material fogAsGlass = retypedMaterial(originals[0], MaterialType::Glass);
    EXPECT_TRUE(fogAsGlass.hasInterior);
    EXPECT_EQ(fogAsGlass.sigmaS, glm::vec3(2.0f));
    const Material amberAsMedium = retypedMaterial(originals[1], MaterialType::Medium);
    EXPECT_EQ(amberAsMedium.sigmaA, glm::vec3(0.2f, 2.0f, 4.0f));
    EXPECT_FALSE(amberAsMedium.hasInterior);
    EXPECT_EQ(retypedMaterial(originals[2], MaterialType::Medium).sigmaS, glm::vec3(1.0f)) << "a fog to see";
    EXPECT_FALSE(retypedMaterial(originals[1], MaterialType::Diffuse).boundsMedium());
}

// The script sets a medium's coefficients and g and a glass's interior; undo takes one back; the
// saved scene reads back as the very materials of the session.
TEST(ScriptRunner, MediaEditedByScriptAreSavedAndReadBackTheSame) {
    testing::ScratchFiles files("script_media");
    const std::filesystem::path saved = files.directory() / "saved.json";
    ScriptedSession run(writeMediaScene(files),
                        "set-material fog.sigma-s 2 1 0.5\nset-material fog.g -0.5\nset-material fog.sigma-a 0 0 0\n"
                        "set-material ball.sigma-a 0.2 2 4\nset-material ball.g 0.25\nundo\nsave-scene " + saved.string() + "\n");
    ASSERT_EQ(run.runner.exitCode(), 0);
    const Material& fog = run.material("fog");
    EXPECT_EQ(fog.sigmaS, glm::vec3(2.0f, 1.0f, 0.5f));
    EXPECT_EQ(fog.sigmaA, glm::vec3(0.0f));
    EXPECT_EQ(fog.g, -0.5f);
    const Material& ball = run.material("ball");
    EXPECT_TRUE(ball.hasInterior);
    EXPECT_EQ(ball.sigmaA, glm::vec3(0.2f, 2.0f, 4.0f));
    EXPECT_EQ(ball.g, 0.0f) << "undone";
    EXPECT_EQ(run.session->history().undoLabel(), "absorption of 'ball'");
    EXPECT_EQ(run.session->history().redoLabel(), "g of 'ball'");

    const Scene again = loadScene(saved);
    const std::vector<Material>& edited = run.session->model().scene.materials;
    ASSERT_EQ(again.materials.size(), edited.size());
    for (std::size_t i = 0; i < edited.size(); ++i)
        EXPECT_TRUE(sameMaterial(again.materials[i], edited[i])) << edited[i].name;
}

// interior on / off: a clear solid, then a thin surface again, each one undo step; a type that
// does not refract has no interior, and a medium's fields need a medium.
TEST(ScriptRunner, InteriorTurnsOnAndOffAndOnlyWhereAMaterialRefracts) {
    testing::ScratchFiles files("script_media");
    const std::filesystem::path scene = writeMediaScene(files);
    ScriptedSession run(scene, "set-material ball.interior off\n");
    ASSERT_EQ(run.runner.exitCode(), 0);
    EXPECT_FALSE(run.material("ball").boundsMedium());
    EXPECT_EQ(run.session->history().undoLabel(), "interior of 'ball'");

    ScriptedSession on(scene, "set-material ball.interior off\nset-material ball.interior on\n");
    ASSERT_EQ(on.runner.exitCode(), 0);
    EXPECT_TRUE(on.material("ball").hasInterior);
    EXPECT_EQ(on.material("ball").sigmaA + on.material("ball").sigmaS, glm::vec3(0.0f)) << "a clear solid";

    ScriptedSession diffuse(scene, "set-material floor.interior on\n");
    EXPECT_EQ(diffuse.runner.exitCode(), 2);
    EXPECT_FALSE(diffuse.material("floor").hasInterior);
    ScriptedSession thin(scene, "set-material ball.interior off\nset-material ball.sigma-a 1 1 1\n");
    EXPECT_EQ(thin.runner.exitCode(), 2);
    EXPECT_EQ(thin.material("ball").sigmaA, glm::vec3(0.0f));
}

// A medium on a quad, by a type change or an interior, is refused at its line (exit 2) with the
// shape named, and the scene keeps the material as it was; a closed shape takes it.
TEST(ScriptRunner, AMediumOnAShapeThatEnclosesNoneIsRefusedAndTheSceneStays) {
    testing::ScratchFiles files("script_media");
    const std::filesystem::path scene = writeMediaScene(files);
    for (const char* edit : {"set-material pane.interior on\n", "set-material pane.type medium\n", "set-material floor.type glass\nset-material floor.interior on\n"}) {
        ScriptedSession run(scene, edit);
        EXPECT_EQ(run.runner.exitCode(), 2) << edit;
        for (const Material& material : run.session->model().scene.materials)
            if (material.name == "pane" || material.name == "floor") {
                EXPECT_FALSE(material.boundsMedium()) << edit;
            }
        EXPECT_TRUE(run.session->history().refused().empty()) << run.session->history().refused();
    }
    ScriptedSession fogged(scene, "set-material ball.type medium\nset-material fog.type glass\n");
    EXPECT_EQ(fogged.runner.exitCode(), 0);
    EXPECT_EQ(fogged.material("ball").type, MaterialType::Medium);
    EXPECT_EQ(fogged.material("ball").sigmaS, glm::vec3(0.0f)) << "the ball's clear interior carries over";
    EXPECT_TRUE(fogged.material("fog").hasInterior) << "the fog carries over into the glass";
    EXPECT_EQ(fogged.material("fog").sigmaS, glm::vec3(0.6f));
}

} // namespace
} // namespace ptview
