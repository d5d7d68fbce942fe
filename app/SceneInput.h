#pragma once
// A scene file and the environment map it names, both read before any window or GPU work, so
// that a bad file is reported as bad input (exit code 2) and nothing else happens.

#include "EnvironmentMap.h"
#include "Scene.h"

#include <optional>
#include <string>

namespace ptview {

struct SceneInput {
    Scene scene;
    std::optional<EnvironmentMap> environmentMap;

    const EnvironmentMap* environmentMapOrNull() const { return environmentMap ? &*environmentMap : nullptr; }
};

// Prints "ptview: FILE: ..." on stderr and returns nullopt when a file is bad.
std::optional<SceneInput> loadSceneInput(const std::string& scenePath);

} // namespace ptview
