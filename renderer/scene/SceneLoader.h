#pragma once
// Reads scene files (JSON, described in docs/scene-format.md) into the scene model of Scene.h.

#include <ptview/scene/ReadScope.h>
#include <ptview/scene/Scene.h>
#include <ptview/scene/SceneError.h>

#include <filesystem>
#include <string>

namespace ptview {

// Throws SceneError naming the file and the place in it. Every file the scene names (meshes, their
// MTL libraries and maps, textures, glTF files, the environment map) must be one `scope` allows.
Scene loadScene(const std::filesystem::path& path, const ReadScope& scope = ReadScope());
// Same, for text already in memory; sourceName is used in error messages and as Scene::path, and
// relative paths are resolved against its directory.
Scene parseScene(const std::string& jsonText, const std::filesystem::path& sourceName, const ReadScope& scope = ReadScope());

} // namespace ptview
