#include <ptview/window/PanelWidgets.h>
#include <ptview/window/Panels.h>
#include <ptview/io/PrintableText.h>
#include <ptview/model/NearbyFiles.h>
#include <ptview/scene/SceneRanges.h>

#include <imgui.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

namespace ptview {
namespace {

// Whether the last load error is a map's rather than a scene file's. A map's error begins with
// its file name ("FILE: reason"): an .hdr, or whatever the user typed into this panel.
bool isMapError(const std::string& error, const std::string& typedPath) {
    if (error.empty()) return false;
    if (!typedPath.empty() && error.rfind(typedPath + ": ", 0) == 0) return true;
    return std::filesystem::path(error.substr(0, error.find(": "))).extension() == ".hdr";
}

} // namespace

void drawEnvironmentPanel(ViewerSession& session, PanelState& state) {
    ViewerModel& model = session.model();
    Scene& scene = model.scene;
    bool hasMap = !scene.environmentMap.empty();
    ImGui::PushTextWrapPos(0.0f);
    ImGui::Text("map: %s", hasMap ? printableText(nameRelativeToScene(scene.environmentMap, scene.path).string()).c_str()
                                  : "none (constant colour)");
    ImGui::PopTextWrapPos();

    ImGui::PushID("environment");
    // Maps near the scene (its folder, hdr/, ../hdr/), named as the scene file will store them.
    const std::filesystem::path& scenePath = scene.path;
    std::optional<std::filesystem::path> picked = fileCombo(
        "maps", [&scenePath] { return environmentMapsNear(scenePath, std::filesystem::path(assetsDirectory()) / "hdr"); },
        scene.environmentMap, "no .hdr files beside the scene, in its hdr/ or in ../hdr/: type a path below",
        [&scenePath](const std::filesystem::path& file) { return nameRelativeToScene(file, scenePath); });
    if (picked) session.setEnvironmentMap(*picked);
    if (pathField("Load", state.environmentPathInput)) session.setEnvironmentMap(state.environmentPathInput);
    ImGui::BeginDisabled(!hasMap);
    if (ImGui::Button("Remove map")) session.setEnvironmentMap({});
    ImGui::EndDisabled();
    ImGui::PopID();
    if (isMapError(model.sceneError, state.environmentPathInput)) errorText(model.sceneError);

    const SceneRange& intensity = ranges::kEnvironmentIntensity;
    bool changed = ImGui::DragFloat("intensity", &scene.environmentIntensity, 0.01f, intensity.panelLo,
                                    intensity.panelHi, "%.3f", ImGuiSliderFlags_AlwaysClamp);
    itemTooltip("scales the map's radiance (not the constant colour)");
    const SceneRange& rotation = ranges::kEnvironmentRotation;
    if (ImGui::SliderFloat("rotation", &scene.environmentRotationDeg, rotation.panelLo, rotation.panelHi, "%.1f deg")) {
        // Ctrl+click lets the user type any angle; keep the shown value in the slider's range.
        scene.environmentRotationDeg -= 360.0f * std::floor(scene.environmentRotationDeg / 360.0f);
        changed = true;
    }
    itemTooltip("turns the map about +Y (right-hand rule)");
    if (ImGui::ColorEdit3("colour", &scene.environment.x, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR)) {
        scene.environment = glm::clamp(scene.environment, ranges::kRadiance.panelLo, ranges::kRadiance.panelHi);
        changed = true;
    }
    itemTooltip("radiance of escaping rays when there is no map; unused while a map is loaded");
    if (changed) model.pendingChanges |= ViewerModel::kSceneChanged;
}

} // namespace ptview
