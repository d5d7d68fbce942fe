// The Interface panel: the UI scale and the high-contrast theme (UserPreferences.h). The window
// applies them and keeps them for the next run (Viewer.cpp, applyInterface).
#include <ptview/window/PanelWidgets.h>
#include <ptview/window/Panels.h>

#include <imgui.h>

namespace ptview {

void drawInterfacePanel(PanelState& state) {
    UserPreferences& preferences = state.preferences;
    // Applied when the drag ends: a style rebuilt under the pointer every frame would move the
    // slider away from it. Meanwhile the slider shows the value being dragged.
    float& dragged = state.uiScaleDragged;
    float scale = dragged > 0.0f ? dragged : preferences.uiScale;
    ImGui::SliderFloat("UI scale", &scale, kUiScale.panelLo, kUiScale.panelHi, "%.2f x", ImGuiSliderFlags_AlwaysClamp);
    if (ImGui::IsItemActive()) {
        dragged = scale;
    } else {
        if (ImGui::IsItemDeactivatedAfterEdit()) preferences.uiScale = clampedUiScale(scale, nullptr);
        dragged = 0.0f;
    }
    itemTooltip("size of the text and widgets, on top of the monitor's scale (Ctrl + / Ctrl -; Ctrl 0: 1x);\n"
                "kept for the next run in ~/.config/ptview/viewer.json");
    ImGui::Checkbox("high contrast", &preferences.highContrast);
    itemTooltip("black panels, white text, bordered fields and strong accents: for projectors and bright rooms");
}

} // namespace ptview
