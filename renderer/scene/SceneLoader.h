#pragma once
// Reads scene files (JSON, described in docs/scene-format.md) into the scene model of Scene.h.

#include "Scene.h"

#include <filesystem>
#include <stdexcept>
#include <string>

namespace ptview {

// A scene file that cannot be used. what() reads "FILE: /json/pointer: reason" or, for
// malformed JSON, "FILE:LINE:COLUMN: reason", on one line.
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws SceneError naming the file and the place in it.
Scene loadScene(const std::filesystem::path& path);
// Same, for text already in memory; sourceName is used in error messages and as Scene::path.
Scene parseScene(const std::string& jsonText, const std::filesystem::path& sourceName);

} // namespace ptview
