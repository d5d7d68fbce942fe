#include <ptview/model/NearbyFiles.h>
#include <ptview/window/PanelWidgets.h>
#include <ptview/window/Panels.h>
#include <ptview/io/PrintableText.h>

#include <imgui.h>

#include <filesystem>
#include <optional>

namespace ptview {

void drawScenePanel(ViewerSession& session, PanelState& state) {
    const ViewerModel& model = session.model();
    // fileScene's path, not scene's: it is the file Reload reads and the watcher follows.
    const std::filesystem::path& file = model.fileScene.path;
    ImGui::PushTextWrapPos(0.0f);
    ImGui::Text("file: %s", file.empty() ? "none (built in code, or carried by an image: Save asks for a name)" : printableText(file.string()).c_str());
    ImGui::PopTextWrapPos();

    ImGui::PushID("scene");
    std::optional<std::filesystem::path> picked =
        fileCombo("scenes", [] { return filesWithExtension(std::filesystem::path(assetsDirectory()) / "scenes", ".json"); },
                  file, "no scenes shipped with ptview found", [](const std::filesystem::path& path) { return path.filename(); });
    if (pathField("Open", state.scenePathInput)) picked = state.scenePathInput;
    if (picked) state.unsavedEdits.request(session, UnsavedEditsPrompt::Action::OpenScene, *picked);
    ImGui::PopID();

    ImGui::BeginDisabled(file.empty());
    if (ImGui::Button("Reload")) state.unsavedEdits.request(session, UnsavedEditsPrompt::Action::Reload);
    ImGui::EndDisabled();
    itemTooltip("read the file again; with unsaved edits it asks first (Discard reads the file as it is)");
    noteText("a change on disk reloads automatically and keeps your edits to what it did not change");

    if (!model.sceneError.empty()) errorText(model.sceneError);
    if (!model.notice.empty()) noteText(model.notice); // a line per warning
}

} // namespace ptview
