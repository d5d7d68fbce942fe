#include <ptview/model/SceneInput.h>

#include <ptview/io/PrintableText.h>
#include <ptview/scene/SceneLoader.h>

namespace ptview {

std::optional<SceneInput> loadSceneInput(const std::string& scenePath,
                                         const std::vector<std::filesystem::path>& allowedDirectories, ReadScope* scope) {
    SceneInput input;
    input.allowedDirectories = allowedDirectories;
    const ReadScope anywhere = ReadScope::anywhere(allowedDirectories);
    if (scope) *scope = anywhere;
    try {
        input.scene = loadScene(scenePath, anywhere);
        for (const std::string& warning : input.scene.warnings) printMessage("warning: " + warning);
        if (!input.scene.environmentMap.empty()) input.environmentMap = loadEnvironmentMap(input.scene.environmentMap);
    } catch (const SceneError& e) {
        printMessage(e.what());
        return std::nullopt;
    } catch (const EnvironmentMapError& e) {
        printMessage(e.what());
        return std::nullopt;
    }
    return input;
}

} // namespace ptview
