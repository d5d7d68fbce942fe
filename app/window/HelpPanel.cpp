#include <ptview/window/PanelWidgets.h>
#include <ptview/window/Panels.h>

#include <imgui.h>

namespace ptview {
namespace {

struct Shortcut {
    const char* keys;
    const char* action;
};

constexpr Shortcut kShortcuts[] = {
    {"Left drag", "orbit"},
    {"Right or middle drag", "pan"},
    {"Shift+left drag", "pan"},
    {"Wheel", "zoom the camera"},
    {"Ctrl+wheel", "pixel zoom of the image about the pointer (1:1, 2:1, 4:1 ...; nearest pixels)"},
    {"Ctrl+right or middle drag", "pan the zoomed image"},
    {"0 / 1 / + / -", "image fit / 1:1 / zoom in / zoom out"},
    {"V", "next view: image, error map, estimated error, difference, absolute difference, other image, samples per pixel"},
    {"Alt+click", "pin the pixel under the cursor in the Pixel panel (again: unpin)"},
    {"Ctrl+click", "focus the lens on the surface under the cursor (Camera panel's aperture)"},
    {"W A S D", "fly (Shift: faster)"},
    {"Q E", "down / up (Shift: faster)"},
    {"F", "reset camera"},
    {"Ctrl+Z", "undo the last edit of a material, texture, light, the camera or the environment (the Edit section names it)"},
    {"Ctrl+Shift+Z, Ctrl+Y", "redo the undone edit"},
    {"Space", "pause / resume"},
    {"R", "restart accumulation"},
    {"C", "toggle the compare split view; drag the white divider to move it"},
    {"N", "denoise on / off (biased; Render panel: strength, iterations, raw | denoised split)"},
    {"F12", "screenshot (PNG + PFM + EXR into screenshots/)"},
    {"Tab", "hide / show the sidebar"},
    {"Ctrl + / Ctrl -", "larger / smaller interface (Ctrl 0: back to 1x; kept for the next run)"},
    {"F1", "this help"},
    {"Esc", "quit (asks first when the scene has unsaved edits)"},
};

} // namespace

void drawHelpPanel() {
    if (ImGui::BeginTable("shortcuts", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
        ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthStretch);
        for (const Shortcut& shortcut : kShortcuts) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(shortcut.keys);
            ImGui::TableNextColumn();
            ImGui::PushTextWrapPos(0.0f); // wraps at the column's edge
            ImGui::TextUnformatted(shortcut.action);
            ImGui::PopTextWrapPos();
        }
        ImGui::EndTable();
    }
    noteText("Edit the scene JSON or a shader on disk: the viewer reloads it; errors show in Scene / Render.");
}

} // namespace ptview
