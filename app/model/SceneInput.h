#pragma once
// A scene file and the environment map it names, both read before any window or GPU work, so
// that a bad file is reported as bad input (exit code 2) and nothing else happens.

#include <ptview/scene/EnvironmentMap.h>
#include <ptview/scene/ReadScope.h>
#include <ptview/scene/Scene.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ptview {

struct SceneInput {
    Scene scene;
    std::optional<EnvironmentMap> environmentMap;
    // The folders the user allowed (--allow-dir), for the scenes opened after this one.
    std::vector<std::filesystem::path> allowedDirectories;
    // The image whose metadata carried the scene (SceneFromImage.h), empty for a scene file. Such
    // a scene has no file of its own: its Scene::path is what the image claims, which sets no
    // save or reload target (docs/robustness.md).
    std::filesystem::path carriedBy;
    // For a carried scene: whether the file it names holds exactly this scene, as far as the
    // image's trust boundary lets us read that file (SceneFromImage.h). When it does not, or
    // cannot be read, the scene exists only in the image: the viewer counts it as unsaved.
    bool carriedSceneIsInItsFile = false;

    const EnvironmentMap* environmentMapOrNull() const { return environmentMap ? &*environmentMap : nullptr; }
};

// Prints "ptview: FILE: ..." on stderr and returns nullopt when a file is bad. The scene reads any
// file it names; its glTF files read only beside themselves and in `allowedDirectories`.
// `scope`, when given, records the files it refused (what the viewer offers to allow).
std::optional<SceneInput> loadSceneInput(const std::string& scenePath,
                                         const std::vector<std::filesystem::path>& allowedDirectories = {},
                                         ReadScope* scope = nullptr);

} // namespace ptview
