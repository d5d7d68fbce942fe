// The undo history of the viewer's scene edits (app/model/EditHistory.h), without a session: steps
// recorded when an edit ends, undo and redo, redo dropped by a new edit, the bound on steps, the
// renderer flags a restore needs, the names of the steps, states the scene format would refuse,
// and a reload rebasing every state onto the file's new contents.
#include <ptview/model/EditHistory.h>
#include <ptview/model/ViewerModel.h>

#include <gtest/gtest.h>

#include <string>

namespace ptview {
namespace {

Material namedMaterial(const std::string& name, MaterialType type, glm::vec3 color, float roughness = 0.0f) {
    Material material;
    material.name = name;
    material.type = type;
    material.color = color;
    material.roughness = roughness;
    return material;
}

// A file's scene as far as the history sees it: a camera, two materials, a spot light.
Scene fileScene() {
    Scene scene;
    scene.camera.eye = {0.0f, 1.0f, 4.0f};
    scene.camera.target = {0.0f, 1.0f, 0.0f};
    scene.materials = {namedMaterial("floor", MaterialType::Metal, glm::vec3(0.8f), 0.1f),
                       namedMaterial("wall", MaterialType::Diffuse, glm::vec3(0.5f))};
    Light key;
    key.name = "key";
    key.type = LightType::Spot;
    key.position = {0.0f, 3.0f, 0.0f};
    key.intensity = glm::vec3(10.0f);
    scene.lights = {key};
    Shape floor;
    floor.type = ShapeType::Quad;
    scene.shapes = {floor};
    return scene;
}

SceneTexture texture(const std::string& file) {
    SceneTexture texture;
    texture.source = file;
    texture.file = file;
    return texture;
}

Material& material(Scene& scene, const std::string& name) {
    for (Material& m : scene.materials)
        if (m.name == name) return m;
    throw std::runtime_error("no material " + name);
}

const Material& material(const SceneEdits& edits, const std::string& name) {
    for (const Material& m : edits.materials)
        if (m.name == name) return m;
    throw std::runtime_error("no material " + name);
}

struct History : ::testing::Test {
    Scene scene = fileScene();
    EditHistory history;

    void SetUp() override { history.reset(SceneEdits::of(scene)); }
    bool record(bool inProgress = false) { return history.record(scene, nullptr, inProgress); }
    // What the session does: the state undo goes to, then the move.
    SceneEdits undo() {
        EXPECT_TRUE(history.canUndo());
        SceneEdits state = *history.undoTarget();
        history.undo();
        state.applyTo(scene);
        return state;
    }
    SceneEdits redo() {
        EXPECT_TRUE(history.canRedo());
        SceneEdits state = *history.redoTarget();
        history.redo();
        state.applyTo(scene);
        return state;
    }
};

TEST_F(History, AnEditIsAStepThatUndoAndRedoWalkBackAndForth) {
    EXPECT_FALSE(history.canUndo());
    EXPECT_FALSE(record()) << "nothing changed";
    material(scene, "floor").roughness = 0.5f;
    EXPECT_TRUE(record());
    EXPECT_FALSE(record()) << "the same scene again is no second step";
    EXPECT_EQ(history.undoSteps(), 1u);
    EXPECT_EQ(history.undoLabel(), "roughness of 'floor'");
    EXPECT_EQ(history.redoLabel(), "");

    EXPECT_FLOAT_EQ(material(undo(), "floor").roughness, 0.1f);
    EXPECT_FALSE(history.canUndo());
    EXPECT_EQ(history.redoLabel(), "roughness of 'floor'");
    EXPECT_FALSE(record()) << "the scene is the state undone to";
    EXPECT_FLOAT_EQ(material(redo(), "floor").roughness, 0.5f);
    EXPECT_FALSE(history.canRedo());
    EXPECT_TRUE(history.canUndo());
}

// A slider held over many frames, a drag, a burst of wheel notches: the session records every
// frame with inProgress until the edit ends, and it is one step from where it began.
TEST_F(History, AnEditInProgressOverManyFramesIsOneStep) {
    for (int frame = 1; frame <= 30; ++frame) {
        material(scene, "floor").roughness = 0.1f + 0.02f * float(frame);
        EXPECT_FALSE(record(true));
    }
    EXPECT_TRUE(record(false)) << "released";
    EXPECT_EQ(history.undoSteps(), 1u);
    EXPECT_FLOAT_EQ(material(undo(), "floor").roughness, 0.1f) << "back to before the drag, not one frame of it";

    // A drag that comes back to where it started is no step at all.
    scene.camera.eye.x = 2.0f;
    EXPECT_FALSE(record(true));
    scene.camera.eye.x = 0.0f;
    EXPECT_FALSE(record(false));
    EXPECT_FALSE(history.canUndo());
}

TEST_F(History, ANewEditDropsTheStepsToRedo) {
    material(scene, "floor").roughness = 0.5f;
    record();
    material(scene, "wall").color = glm::vec3(0.9f, 0.1f, 0.1f);
    record();
    undo();
    undo();
    EXPECT_EQ(history.redoSteps(), 2u);
    scene.camera.vfovDeg = 60.0f;
    EXPECT_TRUE(record());
    EXPECT_FALSE(history.canRedo()) << "the undone edits are another branch, gone";
    EXPECT_EQ(history.undoSteps(), 1u);
    EXPECT_EQ(history.undoLabel(), "field of view");
}

TEST(EditHistory, KeepsAtMostItsBoundOfStepsDroppingTheOldest) {
    Scene scene = fileScene();
    EditHistory history(3);
    history.reset(SceneEdits::of(scene));
    for (int i = 1; i <= 5; ++i) {
        material(scene, "floor").roughness = 0.1f * float(i + 1);
        ASSERT_TRUE(history.record(scene, nullptr));
    }
    EXPECT_EQ(history.undoSteps(), 3u);
    EXPECT_EQ(history.maxSteps(), 3u);
    float roughness = 0.0f;
    while (history.canUndo()) {
        roughness = material(*history.undoTarget(), "floor").roughness;
        history.undo();
    }
    EXPECT_FLOAT_EQ(roughness, 0.3f) << "the state after the second edit is the oldest kept";
    EXPECT_EQ(history.redoSteps(), 3u);
}

// What a restore tells the renderer, as the panels flag the same edits.
TEST(EditHistory, ARestoreFlagsWhatTheRendererMustRedoAndNoMore) {
    const Scene file = fileScene();
    const SceneEdits before = SceneEdits::of(file);
    auto changes = [&](auto edit) {
        Scene edited = file;
        edit(edited);
        return changesBetween(before, SceneEdits::of(edited));
    };
    EXPECT_EQ(changes([](Scene&) {}), 0u);
    EXPECT_EQ(changes([](Scene& s) { material(s, "floor").roughness = 0.4f; }), unsigned(ViewerModel::kMaterialsChanged));
    EXPECT_EQ(changes([](Scene& s) { material(s, "wall").type = MaterialType::Mirror; }), unsigned(ViewerModel::kMaterialsChanged));
    EXPECT_EQ(changes([](Scene& s) { s.camera.eye.z = 5.0f; }), unsigned(ViewerModel::kCameraChanged));
    EXPECT_EQ(changes([](Scene& s) { s.camera.focusDistance = 2.0f; }), unsigned(ViewerModel::kCameraChanged));
    EXPECT_EQ(changes([](Scene& s) { s.lights[0].intensity = glm::vec3(5.0f); }), unsigned(ViewerModel::kSceneChanged));
    EXPECT_EQ(changes([](Scene& s) { s.environmentIntensity = 2.0f; }), unsigned(ViewerModel::kSceneChanged));
    EXPECT_EQ(changes([](Scene& s) { s.environmentMap = "sky.hdr"; }), unsigned(ViewerModel::kSceneChanged));
    EXPECT_EQ(changes([](Scene& s) {
                  s.textures.push_back(texture("t.png"));
                  material(s, "wall").type = MaterialType::Principled;
                  material(s, "wall").baseColorTexture.texture = 0;
              }),
              unsigned(ViewerModel::kSceneChanged))
        << "a texture is uploaded with the scene";
    EXPECT_EQ(changes([](Scene& s) {
                  material(s, "floor").roughness = 0.4f;
                  s.camera.vfovDeg = 30.0f;
              }),
              unsigned(ViewerModel::kMaterialsChanged | ViewerModel::kCameraChanged));
}

TEST(EditHistory, AStepIsNamedByWhatItChanged) {
    const Scene file = fileScene();
    auto label = [&](auto edit) {
        Scene edited = file;
        edit(edited);
        return describeEdit(SceneEdits::of(file), SceneEdits::of(edited));
    };
    EXPECT_EQ(label([](Scene& s) { material(s, "floor").roughness = 0.4f; }), "roughness of 'floor'");
    EXPECT_EQ(label([](Scene& s) { material(s, "wall").color = glm::vec3(0.1f); }), "albedo of 'wall'");
    EXPECT_EQ(label([](Scene& s) { material(s, "floor").color = glm::vec3(0.1f), material(s, "floor").roughness = 0.4f; }),
              "reflectance and roughness of 'floor'");
    EXPECT_EQ(label([](Scene& s) { material(s, "wall").type = MaterialType::Glass; }), "type of 'wall'");
    EXPECT_EQ(label([](Scene& s) { material(s, "wall").radiance = glm::vec3(1.0f); }), "emission of 'wall'");
    EXPECT_EQ(label([](Scene& s) {
                  s.textures.push_back(texture("t.png"));
                  material(s, "wall").baseColorTexture.texture = 0;
              }),
              "base color texture of 'wall'");
    EXPECT_EQ(label([](Scene& s) { material(s, "wall").color.r = 0.2f, material(s, "floor").roughness = 0.3f; }), "2 materials");
    EXPECT_EQ(label([](Scene& s) { s.lights[0].intensity = glm::vec3(1.0f); }), "intensity of light 'key'");
    EXPECT_EQ(label([](Scene& s) { s.lights[0].innerAngleDeg = 30.0f, s.lights[0].outerAngleDeg = 40.0f; }),
              "inner angle and outer angle of light 'key'");
    EXPECT_EQ(label([](Scene& s) { s.camera.eye.x = 1.0f; }), "camera");
    EXPECT_EQ(label([](Scene& s) { s.camera.vfovDeg = 50.0f; }), "field of view");
    EXPECT_EQ(label([](Scene& s) { s.camera.focusDistance = 3.0f; }), "focus distance");
    EXPECT_EQ(label([](Scene& s) { s.environmentMap = "sky.hdr"; }), "environment map");
    EXPECT_EQ(label([](Scene& s) { s.environmentIntensity = 3.0f; }), "environment intensity");
    EXPECT_EQ(label([](Scene& s) { s.environmentRotationDeg = 90.0f; }), "environment rotation");
    EXPECT_EQ(label([](Scene& s) { s.camera.eye.x = 1.0f, s.environmentIntensity = 3.0f; }), "camera and environment intensity");
}

// "An undo history never holds a state the scene format would refuse": such a state is not
// recorded, and undo goes back to the last good one.
TEST_F(History, AStateTheSceneFormatWouldRefuseIsNeverRecorded) {
    material(scene, "floor").roughness = 0.5f;
    ASSERT_TRUE(record());
    scene.camera.eye.x = 2e9f; // typed into the Camera panel's eye: beyond the format's 1e9 m
    EXPECT_FALSE(record());
    EXPECT_NE(history.refused().find("beyond 1e9 m"), std::string::npos) << history.refused();
    EXPECT_EQ(history.current().camera.eye.x, 0.0f) << "the last good state stays the current one";
    EXPECT_EQ(history.undoSteps(), 1u);
    for (auto refuse : {+[](Scene& s) { material(s, "wall").color = glm::vec3(1.5f); },
                        +[](Scene& s) { s.lights[0].innerAngleDeg = 50.0f; }, // past the outer 30
                        +[](Scene& s) { s.lights[0].direction = glm::vec3(0.0f); },
                        +[](Scene& s) { s.environmentIntensity = -1.0f; },
                        +[](Scene& s) { material(s, "wall").type = MaterialType::Principled, material(s, "wall").normalTexture.texture = 3; }}) {
        Scene refused = scene;
        refused.camera = history.current().camera;
        refuse(refused);
        EXPECT_FALSE(history.record(refused, nullptr));
        EXPECT_FALSE(history.refused().empty());
    }
    scene.camera.eye.x = 2.0f; // fixed: a good state is recorded again
    EXPECT_TRUE(record());
    EXPECT_TRUE(history.refused().empty());
    EXPECT_EQ(history.undoSteps(), 2u);
}

// A problem the file itself has (a loader laxer than the checks) does not stop later edits.
TEST(EditHistory, AProblemTheFileAlreadyHadDoesNotStopEdits) {
    Scene scene = fileScene();
    scene.lights[0].innerAngleDeg = 45.0f; // beyond the outer angle, as no file the loader reads has it
    EditHistory history;
    history.reset(SceneEdits::of(scene));
    material(scene, "floor").roughness = 0.6f;
    EXPECT_TRUE(history.record(scene, nullptr));
}

// A reload merges the file's new contents with the user's edits; every state of the history is
// merged the same way, so undo goes back through the user's own edits on top of the new file.
TEST_F(History, AReloadRebasesEveryStateOntoTheNewFile) {
    const Scene oldFile = scene;
    material(scene, "floor").roughness = 0.5f;
    record();
    material(scene, "wall").color = glm::vec3(0.9f, 0.1f, 0.1f);
    record();
    scene.camera.vfovDeg = 55.0f;
    record();
    EXPECT_EQ(history.undoSteps(), 3u);

    // The file: a brighter light, and another colour of the wall (which the user edited too: the file wins).
    Scene newFile = oldFile;
    newFile.lights[0].intensity = glm::vec3(40.0f);
    material(newFile, "wall").color = glm::vec3(0.2f, 0.2f, 0.8f);
    newFile.shapes.push_back(Shape{});
    Scene merged = newFile;
    material(merged, "floor").roughness = 0.5f;
    merged.camera.vfovDeg = 55.0f;
    history.rebase(oldFile, newFile, SceneEdits::of(merged));
    EXPECT_TRUE(sameEdits(history.current(), merged));
    EXPECT_EQ(history.undoSteps(), 2u) << "the wall's step changes nothing now: it went";
    EXPECT_EQ(history.undoLabel(), "field of view");

    SceneEdits state = *history.undoTarget();
    history.undo();
    EXPECT_EQ(state.camera.vfovDeg, 40.0f);
    EXPECT_FLOAT_EQ(material(state, "floor").roughness, 0.5f);
    EXPECT_EQ(state.lights[0].intensity, glm::vec3(40.0f)) << "the file's light in every state";
    EXPECT_EQ(material(state, "wall").color, glm::vec3(0.2f, 0.2f, 0.8f));
    state = *history.undoTarget();
    history.undo();
    EXPECT_FLOAT_EQ(material(state, "floor").roughness, 0.1f);
    EXPECT_TRUE(sameEdits(state, newFile)) << "the first state is the new file itself";
    EXPECT_FALSE(history.canUndo());
}

// A state keeps the decoded map it had, or shares the merged scene's where the file's map replaced its own.
TEST(EditHistory, StatesShareTheDecodedEnvironmentMaps) {
    Scene scene = fileScene();
    auto sky = std::make_shared<const EnvironmentMap>();
    auto studio = std::make_shared<const EnvironmentMap>();
    scene.environmentMap = "sky.hdr";
    EditHistory history;
    history.reset(SceneEdits::of(scene, sky));
    scene.environmentMap = "studio.hdr";
    ASSERT_TRUE(history.record(scene, studio));
    EXPECT_EQ(history.undoTarget()->environmentMapData, sky);

    auto skyAgain = std::make_shared<const EnvironmentMap>(); // sky.hdr changed on disk and was read again
    history.shareEnvironmentMap("sky.hdr", skyAgain);
    EXPECT_EQ(history.undoTarget()->environmentMapData, skyAgain);
    EXPECT_EQ(history.current().environmentMapData, studio);
}

// The history refuses a state with a medium in a shape that encloses none, whatever made it (the
// Materials panel and the script take such an edit back first; this is the net under both).
TEST(EditHistory, AStateWithAMediumInAQuadIsRefusedNamingTheShape) {
    Scene scene;
    Material pane;
    pane.name = "pane";
    pane.type = MaterialType::Glass;
    Material ball = pane;
    ball.name = "ball";
    ball.hasInterior = true;
    scene.materials = {pane, ball};
    Shape window;
    window.name = "window";
    window.type = ShapeType::Quad;
    window.material = 0;
    Shape sphere;
    sphere.name = "sphere";
    sphere.material = 1;
    scene.shapes = {window, sphere};
    EditHistory history;
    history.reset(SceneEdits::of(scene));

    scene.materials[0].hasInterior = true;
    EXPECT_FALSE(history.record(scene, nullptr));
    EXPECT_EQ(history.refused(), "shape 'window': a quad encloses no volume, so it cannot bound the medium of material 'pane'");
    EXPECT_FALSE(history.canUndo());
    scene.materials[0].hasInterior = false;
    scene.materials[1].sigmaA = glm::vec3(1.0f);
    EXPECT_TRUE(history.record(scene, nullptr));
    EXPECT_TRUE(history.refused().empty());
    EXPECT_EQ(history.undoLabel(), "absorption of 'ball'");
}

} // namespace
} // namespace ptview
