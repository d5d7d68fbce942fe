#include <ptview/window/PanelWidgets.h>
#include <ptview/window/Panels.h>
#include <ptview/io/PrintableText.h>

#include <imgui.h>

#include <string>

namespace ptview {
namespace {

constexpr const char* kTitle = "Unsaved edits";

std::string joined(const std::vector<std::string>& words) {
    std::string text;
    for (const std::string& word : words) text += (text.empty() ? "" : ", ") + word;
    return text;
}

std::string question(const UnsavedEditsPrompt& prompt) {
    switch (*prompt.pending()) {
    case UnsavedEditsPrompt::Action::Quit: return "Quit without saving them?";
    case UnsavedEditsPrompt::Action::OpenScene: return "Open " + prompt.sceneToOpen().string() + " without saving them?";
    case UnsavedEditsPrompt::Action::Reload: return "Reload the file without them?";
    }
    return "";
}

} // namespace

void drawUnsavedEditsDialog(ViewerSession& session, PanelState& state) {
    UnsavedEditsPrompt& prompt = state.unsavedEdits;
    // The prompt decides when the question is open; the popup follows it (the window's keys
    // answer it too, see Viewer.cpp).
    if (prompt.pending() && !ImGui::IsPopupOpen(kTitle)) ImGui::OpenPopup(kTitle);
    ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(kTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    if (!prompt.pending()) {
        ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
        return;
    }
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 32.0f);
    // Names and paths here may come from a file someone sent: shown through printableText.
    ImGui::Text("The scene has edits that are not saved (%s).", printableText(joined(prompt.edits())).c_str());
    ImGui::TextUnformatted(printableText(question(prompt)).c_str());
    const std::string& target = session.saveTarget();
    bool canSave = !target.empty();
    if (!canSave)
        ImGui::TextDisabled("Save needs a file name: type one in Materials > Save scene as.");
    else if (session.saveReplacesAnotherFile(target))
        ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "Save replaces %s, which is not this scene's file.", printableText(target).c_str());
    else
        ImGui::TextDisabled("Save writes %s.", printableText(target).c_str());
    if (!prompt.saveError().empty()) errorText(prompt.saveError());
    ImGui::PopTextWrapPos();

    ImGui::BeginDisabled(!canSave);
    if (ImGui::Button("Save")) prompt.answer(session, UnsavedEditsPrompt::Answer::Save);
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Discard")) prompt.answer(session, UnsavedEditsPrompt::Answer::Discard);
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) prompt.answer(session, UnsavedEditsPrompt::Answer::Cancel);
    ImGui::TextDisabled("keys: S save, D discard, Esc cancel");
    if (!prompt.pending()) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

} // namespace ptview
