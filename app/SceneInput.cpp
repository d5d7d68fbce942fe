#include "SceneInput.h"

#include "SceneLoader.h"

#include <iostream>

namespace ptview {

std::optional<SceneInput> loadSceneInput(const std::string& scenePath) {
    SceneInput input;
    try {
        input.scene = loadScene(scenePath);
        for (const std::string& warning : input.scene.warnings) std::cerr << "ptview: warning: " << warning << "\n";
        if (!input.scene.environmentMap.empty()) input.environmentMap = loadEnvironmentMap(input.scene.environmentMap);
    } catch (const SceneError& e) {
        std::cerr << "ptview: " << e.what() << "\n";
        return std::nullopt;
    } catch (const EnvironmentMapError& e) {
        std::cerr << "ptview: " << e.what() << "\n";
        return std::nullopt;
    }
    return input;
}

} // namespace ptview
