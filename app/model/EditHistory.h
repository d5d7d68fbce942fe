#pragma once
// Undo and redo of the user's scene edits (docs/viewer.md, "Undo and redo"). The history is a list
// of snapshots of what the user edits (SceneEdits) with a cursor: a step is the move from one
// snapshot to the next, named for the Undo and Redo buttons ("roughness of 'floor'"). Nothing here
// knows where an edit came from: the session records the model after every change (each frame,
// each script command), so a panel, the mouse, a key and a script command are all covered by one
// comparison. An edit still in progress (a slider held, a drag, a burst of wheel notches) is not
// recorded until it ends, which makes it one step however many frames it took.
//
// Plain C++ on the scene model (no GL, no ImGui), so tests/EditHistoryTest.cpp drives it directly.

#include <ptview/scene/EnvironmentMap.h>
#include <ptview/scene/Scene.h>

#include <cstddef>
#include <deque>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace ptview {

// What one undo step restores: every part of the scene the user edits (the Materials, Lights,
// Camera and Environment panels, the mouse and keys, script commands) and nothing else. Shapes,
// meshes and glTF imports change only with the file, so a snapshot holds none of them: a step of a
// million-triangle scene costs its materials, textures (which share their decoded images) and
// lights, a few kilobytes.
struct SceneEdits {
    CameraDesc camera;
    glm::vec3 environment{0.0f};
    std::filesystem::path environmentMap;
    float environmentIntensity = 1.0f;
    float environmentRotationDeg = 0.0f;
    std::vector<Material> materials;
    std::vector<SceneTexture> textures;
    std::vector<Light> lights;
    // The decoded map environmentMap names, shared with the model (ViewerModel::environmentMap), so
    // that undoing a map choice does not read the file again. Null for no map; a cache, never
    // compared (sameEdits compares the path).
    std::shared_ptr<const EnvironmentMap> environmentMapData;

    static SceneEdits of(const Scene& scene, std::shared_ptr<const EnvironmentMap> map = nullptr);
    // Writes every field above but the map's data into scene.
    void applyTo(Scene& scene) const;
    // A scene of these fields alone (no shapes): what the reload merge compares.
    Scene toScene() const;
};

// Whether the two are the same in everything a step restores, floats exactly (every value is one
// typed, dragged or read, never recomputed); the map by its path.
bool sameEdits(const SceneEdits& a, const SceneEdits& b);
bool sameEdits(const SceneEdits& edits, const Scene& scene); // without copying the scene

// The ViewerModel::Change flags that going from `from` to `to` needs, as the panels set them: the
// camera kCameraChanged; a light, the environment, a texture or a material's texture slot
// kSceneChanged (everything is uploaded again); other material parameters kMaterialsChanged alone.
unsigned changesBetween(const SceneEdits& from, const SceneEdits& to);

// What the step from `before` to `after` did, for "Undo: ..." and "Redo: ...": "roughness of
// 'floor'", "colour and roughness of 'floor'", "type of 'glass'", "base color texture of 'floor'",
// "intensity of light 'key'", "camera", "field of view", "environment map", "3 materials",
// "camera and environment intensity". Empty when the two are the same.
std::string describeEdit(const SceneEdits& before, const SceneEdits& after);

// Why the scene format would refuse these edits (SceneRanges.h, the loader's rules for what the UI
// edits: the camera, the environment, each material's inputs of its type and texture slots, each
// light), or empty when it would not. The history never holds a state with a problem.
std::string editsProblem(const SceneEdits& edits);

// Why the scene's shapes could not hold its materials (MediumBoundaries.h: a quad, a disk or an
// open mesh whose material is a medium or holds one, which the loader refuses), or empty: "shape
// 'curtain': a quad encloses no volume, so it cannot bound the medium of material 'fog'". Only a
// change of which materials bound a medium can change it (Material::boundsMedium).
std::string mediumBoundaryProblem(const Scene& scene);

class EditHistory {
public:
    // Steps kept: 100 snapshots of a scene's materials and lights are small, and a session of
    // tweaking rarely wants to go back further.
    static constexpr std::size_t kDefaultMaxSteps = 100;

    explicit EditHistory(std::size_t maxSteps = kDefaultMaxSteps);

    // Starts over at `state`: nothing to undo or redo (a scene opened).
    void reset(SceneEdits state);

    // The scene as it is now. When it differs from current() and no edit is in progress, that
    // difference becomes one step (the steps to redo are dropped, the oldest beyond maxSteps too)
    // and true is returned. While `inProgress` nothing is recorded: the edit is recorded whole
    // when it ends. A state the scene format would refuse (editsProblem, mediumBoundaryProblem) is not recorded either:
    // refused() says why, and undo goes back to current(), the last good state. The step is
    // named `label`, or when that is empty by what changed (describeEdit).
    bool record(const Scene& scene, const std::shared_ptr<const EnvironmentMap>& map, bool inProgress = false,
                std::string label = {});
    // Why the last state offered to record() was refused; empty once one is recorded or matches.
    const std::string& refused() const { return refused_; }

    // The state the history is at: the last one recorded, undone to or redone to.
    const SceneEdits& current() const { return steps_[cursor_].state; }
    bool canUndo() const { return cursor_ > 0; }
    bool canRedo() const { return cursor_ + 1 < steps_.size(); }
    // What undo or redo would do ("roughness of 'floor'"); empty when there is nothing to do.
    std::string undoLabel() const;
    std::string redoLabel() const;
    std::size_t undoSteps() const { return cursor_; }
    std::size_t redoSteps() const { return steps_.size() - 1 - cursor_; }
    std::size_t maxSteps() const { return maxSteps_; }

    // The state undo or redo would go to, or null; then undo() or redo() moves there (the caller
    // restores the state first, so a restore that fails moves nothing).
    const SceneEdits* undoTarget() const { return canUndo() ? &steps_[cursor_ - 1].state : nullptr; }
    const SceneEdits* redoTarget() const { return canRedo() ? &steps_[cursor_ + 1].state : nullptr; }
    void undo();
    void redo();

    // A reload merged the file's new contents with the user's edits (SceneMerge.h): every state is
    // merged the same way, so undo and redo keep walking through the user's own edits on top of
    // the new file. The file wins where it changed an item, in every state; steps that then change
    // nothing are dropped. `now` is the merged scene with its map (its map data serves the states
    // that take the file's map).
    void rebase(const Scene& oldFile, const Scene& newFile, const SceneEdits& now);
    // The map file at `path` was read again (it changed on disk): every state naming it shares it.
    void shareEnvironmentMap(const std::filesystem::path& path, const std::shared_ptr<const EnvironmentMap>& map);

private:
    struct Step {
        SceneEdits state;
        std::string label; // what the step into this state did (empty for the first)
    };

    std::size_t maxSteps_;
    std::deque<Step> steps_; // never empty
    std::size_t cursor_ = 0;
    std::string refused_;
};

} // namespace ptview
