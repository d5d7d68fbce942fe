#include "Integrator.h"
#include "PanelWidgets.h"
#include "Panels.h"
#include "SamplerMode.h"

#include <imgui.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <vector>

namespace ptview {
namespace {

constexpr float kPlotHeight = 60.0f;

void drawErrorPlot(const ViewerSession::ViewStats& stats) {
    // Log scale: the error falls as 1/sqrt(time), so a straight line shows healthy convergence.
    std::vector<float> logErrors;
    logErrors.reserve(stats.errorHistory.size());
    for (const auto& [seconds, error] : stats.errorHistory)
        if (error > 0.0f && std::isfinite(error)) logErrors.push_back(std::log10(error));
    if (logErrors.size() < 2) return;
    char overlay[48];
    std::snprintf(overlay, sizeof overlay, "%.3g %% (log scale)", 100.0 * stats.errorHistory.back().second);
    // An explicit width: PlotLines in ImGui 1.86 does not take -1 to mean "to the right edge".
    ImGui::PlotLines("##error", logErrors.data(), static_cast<int>(logErrors.size()), 0, overlay, FLT_MAX, FLT_MAX,
                     ImVec2(ImGui::GetContentRegionAvail().x, kPlotHeight));
    itemTooltip("log10 of the relative error, about once a second of rendering");
}

void drawViewStats(const ViewerSession& session, ViewerSession::Side side, double frameSeconds) {
    const ViewerModel& model = session.model();
    const RenderSettings& settings = session.settings(side);
    ViewerSession::ViewStats stats = session.stats(side);
    ImGui::Text("%s: %s, %s", side == ViewerSession::Side::Left ? "left" : "right", integratorName(settings.integrator),
                samplerModeName(settings.sampler));
    if (model.targetSamples > 0) {
        ImGui::Text("%d / %d spp%s", stats.samples, model.targetSamples,
                    stats.samples >= model.targetSamples ? "  (target reached)" : "");
    } else {
        ImGui::Text("%d spp", stats.samples);
    }
    glm::ivec2 size = session.renderSize();
    ImGui::Text("%d x %d pixels, %.1f ms/frame", size.x, size.y, frameSeconds * 1e3);
    ImGui::Text("%.2f M samples/s, %.1f s rendering", stats.samplesPerSecond * 1e-6, stats.renderSeconds);
    if (stats.error.relativeError > 0.0)
        ImGui::Text("relative error %.3g %%", stats.error.relativeError * 100.0);
    else
        ImGui::TextUnformatted("relative error -");
    itemTooltip("each pixel's standard error relative to its value (RMS over the image), estimated from the "
                "pixel's own samples;\nthe square root of the relative MSE; measures noise, not bias");
    if (stats.error.nonFinitePixels > 0)
        ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%lld NaN/Inf pixels", stats.error.nonFinitePixels);
    drawErrorPlot(stats);
}

} // namespace

void drawStatsPanel(const ViewerSession& session, double frameSeconds) {
    const ViewerModel& model = session.model();
    if (model.paused)
        ImGui::TextUnformatted("paused (Space resumes)");
    else if (!session.accumulating())
        ImGui::TextUnformatted("target reached");
    else
        ImGui::TextUnformatted("rendering");
    // Frame time is the whole frame's, the same for both views; the rest is each view's own.
    ImGui::PushID("left");
    drawViewStats(session, ViewerSession::Side::Left, frameSeconds);
    ImGui::PopID();
    if (!session.comparing()) return;
    ImGui::Separator();
    ImGui::PushID("right");
    drawViewStats(session, ViewerSession::Side::Right, frameSeconds);
    ImGui::PopID();
}

} // namespace ptview
