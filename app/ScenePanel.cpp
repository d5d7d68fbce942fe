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
    if (picked) session.openScene(*picked);
    if (pathField("Open", state.scenePathInput)) session.openScene(state.scenePathInput);
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
