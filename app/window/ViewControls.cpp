// The Render panel's view controls: what the image shows (DisplayView.h), the colour map's range,
// the image the difference views compare with, and the pixel zoom (ImageZoom.h).
#include <ptview/window/Panels.h>

#include <ptview/window/PanelWidgets.h>
#include <ptview/io/PrintableText.h>

#include <imgui.h>

#include <cmath>
#include <cstdio>

namespace ptview {

void drawViewControls(ViewerSession& session, PanelState& state) {
    ViewerModel& model = session.model();
    DisplaySettings& display = model.display;
    enumCombo("shows (V)", displayViewNames(), display.view);
    ErrorMapRange& range = display.mapRange;
    if (display.view == DisplayView::Error || display.view == DisplayView::EstimatedError) {
        // In percent, log-scaled: the legend's numbers.
        float lo = 100.0f * std::pow(10.0f, range.errorLog10Min), hi = 100.0f * std::pow(10.0f, range.errorLog10Max);
        const float lowest = 100.0f * std::pow(10.0f, kErrorLog10Lowest), highest = 100.0f * std::pow(10.0f, kErrorLog10Highest);
        bool changed = ImGui::SliderFloat("error from", &lo, lowest, highest, "%.3g %%", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
        changed |= ImGui::SliderFloat("error to", &hi, lowest, highest, "%.3g %%", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
        itemTooltip("the colour map's range: relative errors at or below 'from' get its first colour, at or above 'to' its last");
        if (changed && lo < hi) {
            range.errorLog10Min = std::log10(lo / 100.0f);
            range.errorLog10Max = std::log10(hi / 100.0f);
        }
    } else if (display.view == DisplayView::Difference) {
        ImGui::SliderFloat("diff. range", &range.differenceRange, kDifferenceRangeMin, kDifferenceRangeMax, "+-%.3g",
                           ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
        itemTooltip("the colour map's ends: render - other of -range (blue) and +range (red), linear radiance");
    }
    if (viewNeedsOtherImage(display.view)) {
        ImGui::PushID("compare image");
        if (pathField("Load image", state.compareImagePathInput) && !session.setCompareImage(state.compareImagePathInput))
            state.showImageNotice(printableText(model.sceneError), true); // said on the image too; the image before is kept
        itemTooltip("a .pfm or .exr of the render's size to compare with (without one: the reference of the Stats panel)");
        if (model.compareImage) {
            ImGui::TextDisabled("compared with %s", printableText(model.compareImagePath.filename().string()).c_str());
            ImGui::SameLine();
            if (ImGui::SmallButton("none")) session.setCompareImage({});
        }
        ImGui::PopID();
    }
    if (std::string problem = session.viewProblem(ViewerSession::Side::Left); !problem.empty() && !session.comparing())
        noteText(problem);
    // The pixel zoom: fit or a power of two (Ctrl+wheel about the pointer, 0 fit, 1 one to one).
    char zoomText[32];
    if (model.zoom.fit())
        std::snprintf(zoomText, sizeof zoomText, "zoom: fit");
    else
        std::snprintf(zoomText, sizeof zoomText, "zoom: %g:1", static_cast<double>(model.zoom.scale));
    ImGui::TextUnformatted(zoomText);
    ImGui::SameLine();
    if (ImGui::SmallButton("fit (0)")) session.fitImage();
    ImGui::SameLine();
    if (ImGui::SmallButton("1:1 (1)")) session.zoomImageTo(1.0f);
    ImGui::SameLine();
    if (ImGui::SmallButton("-")) session.zoomImageBySteps(-1);
    ImGui::SameLine();
    if (ImGui::SmallButton("+")) session.zoomImageBySteps(1);
    itemTooltip("pixel zoom: each render pixel a block of screen pixels. Ctrl+wheel zooms about the pointer,\n"
                "Ctrl+right or middle drag pans, keys 0 (fit), 1 (1:1), + and -");
}

} // namespace ptview
