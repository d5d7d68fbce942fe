#pragma once
// Hot reload without losing work: when the scene file changes on disk, the new file is merged
// with what the user edited in the UI since the file was last loaded. An edit survives unless the
// file changed the same item too; then the file wins and the edit is reported as overridden.

#include <ptview/scene/Scene.h>

#include <string>
#include <vector>

namespace ptview {

struct SceneMergeResult {
    Scene scene;
    // The user's edits that the file overrode, one human-readable line each, for the viewer to
    // show: `material "glass"`, `light "key"`, `camera`, `environment`, or
    // `material "glass" (removed from the file)`.
    std::vector<std::string> overridden;
};

// A three-way merge. `base` is the scene as last loaded from the file, `edited` is base plus the
// user's edits (the UI's model), `reloaded` is the file's new contents. The items are: each
// material and each light, matched by name; the camera (its resolution always comes from the
// file); the environment (colour, map, intensity and rotation together). The result is
// `reloaded` with each item the user changed and the file did not put back to the user's value.
// Shapes, the order of materials (shapes index them) and lights, and Scene::path come from the
// file. Items that are in `edited` but not in `base` (nothing the UI makes) are left out.
// A material taken from `edited` brings the textures its slots name (found in the result's list
// by source and sampling, or appended to it).
SceneMergeResult mergeReloadedScene(const Scene& base, const Scene& edited, const Scene& reloaded);

} // namespace ptview
