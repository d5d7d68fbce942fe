#pragma once
// Small widgets the sidebar's panels share: hover help, message text, a file picker for an
// assets folder and a typed path with its button. Header only: each is a few lines of ImGui.

#include <ptview/settings/EnumTable.h>
#include <ptview/io/PrintableText.h>

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

namespace ptview {

// The texts these widgets show may quote names, paths and errors from a file someone sent: each
// shows its text through printableLines (PrintableText.h), so a control character reads as an
// escape and a line break stays one.
// Every tooltip wraps at kTooltipWrapEm font sizes: ImGui does not wrap one by itself, and a long
// line wider than the window was cut at its edge (the Trace paths button's, issue 37).
constexpr float kTooltipWrapEm = 36.0f;
inline void wrappedTooltip(const std::string& text) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * kTooltipWrapEm);
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

// Escaped only when shown (hovered): the panels call this for every widget every frame.
inline void itemTooltip(const char* text) {
    if (ImGui::IsItemHovered()) wrappedTooltip(printableLines(text));
}

// A combo over an enum's table: each entry's label, with its description (where it has one) on
// hover, in the list and on the closed combo. Returns whether an entry was picked.
template <typename E>
bool enumCombo(const char* label, const EnumTable<E>& table, E& value) {
    bool picked = false;
    if (ImGui::BeginCombo(label, table.entry(value).displayLabel())) {
        for (const EnumEntry<E>& entry : table) {
            if (ImGui::Selectable(entry.displayLabel(), entry.value == value)) {
                value = entry.value;
                picked = true;
            }
            if (*entry.description) itemTooltip(entry.description);
        }
        ImGui::EndCombo();
    }
    if (*table.entry(value).description) itemTooltip(table.entry(value).description);
    return picked;
}

// Messages carry whole file paths, so they wrap at the panel's edge instead of widening it.
inline void errorText(const std::string& text) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", printableLines(text).c_str());
    ImGui::PopTextWrapPos();
}

inline void noteText(const std::string& text) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", printableLines(text).c_str());
    ImGui::PopTextWrapPos();
}

// The files in directory with this extension (".json"), sorted; none when it cannot be read,
// since a missing assets folder only means an empty list.
// A combo of the files listFiles() returns, each shown as nameOf names it. The files are listed
// only while the combo is open (a few folder reads), so files added while the viewer runs show
// up. Returns the file picked this frame.
template <typename ListFiles, typename NameOf>
std::optional<std::filesystem::path> fileCombo(const char* label, ListFiles listFiles, const std::filesystem::path& current,
                                               const char* whereNone, NameOf nameOf) {
    std::string preview = current.empty() ? "choose..." : printableText(nameOf(current).string());
    if (!ImGui::BeginCombo(label, preview.c_str())) return std::nullopt;
    std::optional<std::filesystem::path> picked;
    const std::vector<std::filesystem::path> files = listFiles();
    if (files.empty()) ImGui::TextDisabled("%s", whereNone);
    for (const std::filesystem::path& file : files) {
        std::error_code error; // `current` may name the same file by another path, or none
        bool isCurrent = !current.empty() && std::filesystem::equivalent(file, current, error);
        if (ImGui::Selectable(printableText(nameOf(file).string()).c_str(), isCurrent)) picked = file;
        if (isCurrent) ImGui::SetItemDefaultFocus();
    }
    ImGui::EndCombo();
    return picked;
}

// A path field with a button on the same line; Enter in the field counts as a click. Returns
// whether the user asked for a non-empty path.
inline bool pathField(const char* buttonLabel, std::string& path) {
    const ImGuiStyle& style = ImGui::GetStyle();
    float buttonWidth = ImGui::CalcTextSize(buttonLabel).x + 2.0f * style.FramePadding.x;
    ImGui::SetNextItemWidth(-(buttonWidth + style.ItemSpacing.x));
    bool submitted = ImGui::InputTextWithHint("##path", "or type a path", &path, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    submitted |= ImGui::Button(buttonLabel);
    return submitted && !path.empty();
}

} // namespace ptview
