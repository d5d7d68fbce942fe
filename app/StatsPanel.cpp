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
    if (stats.trueError) {
        const ErrorMetrics& e = *stats.trueError;
        ImGui::Text("vs reference: relMSE %.3g, RMSE %.3g", e.relativeMse, e.rmse);
        itemTooltip("the true error against the loaded reference image: relative MSE = mean of (x - ref)^2 / (ref^2 + 0.01)");
        ImGui::Text("bias %+.2g %+.2g %+.2g", e.meanBias.r, e.meanBias.g, e.meanBias.b);
        itemTooltip("mean of the image minus mean of the reference, per channel: what more samples cannot remove");
        std::vector<float> logs;
        for (const auto& [seconds, relMse] : stats.trueErrorHistory)
            if (relMse > 0.0f) logs.push_back(std::log10(relMse));
        if (logs.size() >= 2) {
            char overlay[48];
            std::snprintf(overlay, sizeof overlay, "relMSE %.3g (log scale)", double(stats.trueErrorHistory.back().second));
            ImGui::PlotLines("##trueError", logs.data(), static_cast<int>(logs.size()), 0, overlay, FLT_MAX, FLT_MAX,
                             ImVec2(ImGui::GetContentRegionAvail().x, kPlotHeight));
        }
    } else if (model.reference) {
        ImGui::TextDisabled("reference is %dx%d, the render %dx%d: no true error", model.reference->width,
                            model.reference->height, session.renderSize().x, session.renderSize().y);
    }
    if (stats.error.nonFinitePixels > 0)
        ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%lld NaN/Inf pixels", stats.error.nonFinitePixels);
    drawErrorPlot(stats);
}

} // namespace

void drawStatsPanel(ViewerSession& session, PanelState& state, double frameSeconds) {
    const ViewerModel& model = session.model();
    ImGui::PushID("reference");
    if (pathField("Load reference", state.referencePathInput)) session.setReference(state.referencePathInput);
    itemTooltip("a .pfm of this scene at the render's size (e.g. ptview render SCENE --spp 4096 --size WxH --out ref.pfm):\n"
                "the panel then shows the true error against it");
    if (model.reference) {
        ImGui::TextDisabled("reference: %s", model.referencePath.filename().string().c_str());
        ImGui::SameLine();
        if (ImGui::SmallButton("none")) session.setReference({});
    }
    ImGui::PopID();
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
