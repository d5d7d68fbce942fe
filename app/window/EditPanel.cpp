// The sidebar's Edit section (Undo and Redo, each naming its step) and the actions it shares with
// Ctrl+Z, Ctrl+Shift+Z / Ctrl+Y and the script's `undo` and `redo`. The history itself is the
// session's (EditHistory.h); this only draws it and says what happened, on the image too, where
// it is seen with the sidebar hidden.
#include <ptview/window/PanelWidgets.h>
#include <ptview/window/Panels.h>

#include <imgui.h>

#include <chrono>
#include <string>

namespace ptview {
namespace {

// Shown on an ImGui button: its "##" would start the button's hidden id.
std::string buttonText(const std::string& text) {
    std::string shown = printableText(text);
    for (std::size_t at = shown.find("##"); at != std::string::npos; at = shown.find("##", at + 2)) shown.insert(at + 1, " ");
    return shown;
}

bool showOutcome(ViewerSession& session, PanelState& state, bool done) {
    const ViewerModel& model = session.model();
    state.showImageNotice(printableText(done || model.sceneError.empty() ? model.notice : model.sceneError), !done);
    return done;
}

} // namespace

bool undoEdit(ViewerSession& session, PanelState& state) { return showOutcome(session, state, session.undo()); }
bool redoEdit(ViewerSession& session, PanelState& state) { return showOutcome(session, state, session.redo()); }

void drawEditPanel(ViewerSession& session, PanelState& state) {
    const EditHistory& history = session.history();
    const Scene& scene = session.model().scene;
    // An edit the history refused is what Undo takes back first (ViewerSession::undo).
    const bool refusedEdit = !history.refused().empty() && !sameEdits(history.current(), scene);
    const std::string undoLabel = refusedEdit ? describeEdit(history.current(), SceneEdits::of(scene)) : history.undoLabel();
    const std::string redoLabel = history.redoLabel();

    ImGui::BeginDisabled(undoLabel.empty());
    if (ImGui::Button((undoLabel.empty() ? std::string("Undo") : "Undo: " + buttonText(undoLabel)).c_str())) undoEdit(session, state);
    ImGui::EndDisabled();
    itemTooltip("Ctrl+Z: back to the scene as it was before this edit");
    ImGui::BeginDisabled(redoLabel.empty());
    if (ImGui::Button((redoLabel.empty() ? std::string("Redo") : "Redo: " + buttonText(redoLabel)).c_str())) redoEdit(session, state);
    ImGui::EndDisabled();
    itemTooltip("Ctrl+Shift+Z or Ctrl+Y: the undone edit again");
    ImGui::TextDisabled("%zu to undo, %zu to redo (the last %zu edits)", history.undoSteps(), history.redoSteps(),
                        history.maxSteps());
    if (refusedEdit)
        errorText("this edit is not in the history, as a scene file could not hold it (" + history.refused() +
                  "): Undo takes it back");
}

} // namespace ptview
