#include "PanelWidgets.h"
#include "Panels.h"

#include <imgui.h>

#include <filesystem>
#include <optional>

namespace ptview {

void drawScenePanel(ViewerSession& session, PanelState& state) {
    const ViewerModel& model = session.model();
    // fileScene's path, not scene's: it is the file Reload reads and the watcher follows.
    const std::filesystem::path& file = model.fileScene.path;
    ImGui::PushTextWrapPos(0.0f);
    ImGui::Text("file: %s", file.empty() ? "none (built in code)" : file.string().c_str());
    ImGui::PopTextWrapPos();

    ImGui::PushID("scene");
    std::optional<std::filesystem::path> picked =
        fileCombo("scenes", std::filesystem::path(assetsDirectory()) / "scenes", ".json", file);
    if (pathField("Open", state.scenePathInput)) picked = state.scenePathInput;
    if (picked) {
        if (session.hasUnsavedEdits()) {
            state.sceneToOpen = picked->string();
            ImGui::OpenPopup("Unsaved edits");
        } else {
            session.openScene(*picked);
        }
    }
    // Nothing the user made is lost without asking.
    if (ImGui::BeginPopupModal("Unsaved edits", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::Text("The scene has edits that are not saved.\nOpen %s and lose them?", state.sceneToOpen.c_str());
        ImGui::TextDisabled("(Materials > Save scene as keeps them.)");
        if (ImGui::Button("Discard edits and open")) {
            session.openScene(state.sceneToOpen);
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
    ImGui::PopID();

    ImGui::BeginDisabled(file.empty());
    if (ImGui::Button("Reload")) session.reloadScene();
    ImGui::EndDisabled();
    itemTooltip("read the file again, keeping the edits made here to what the file did not change");
    noteText("edits on disk reload automatically; your UI edits are kept");

    if (!model.sceneError.empty()) errorText(model.sceneError);
    if (!model.notice.empty()) noteText(model.notice);
}

} // namespace ptview
