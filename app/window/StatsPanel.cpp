#include <ptview/settings/Integrator.h>
#include <ptview/window/PanelWidgets.h>
#include <ptview/window/PanelText.h>
#include <ptview/window/Panels.h>
#include <ptview/io/PrintableText.h>
#include <ptview/settings/SamplerMode.h>
#include <ptview/tracer/AdaptiveSampler.h>

#include <imgui.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace ptview {
namespace {

constexpr float kPlotHeight = 60.0f;

void drawErrorPlot(const ViewerSession::ViewStats& stats) {
    // Log scale: the error falls as 1/sqrt(time), so a straight line shows healthy convergence.
    std::vector<float> logErrors;
    logErrors.reserve(stats.errorHistory.size());
    for (const auto& [seconds, relativeMse] : stats.errorHistory)
        if (relativeMse > 0.0f && std::isfinite(relativeMse)) logErrors.push_back(std::log10(float(relativeError(relativeMse))));
    if (logErrors.size() < 2) return;
    char overlay[48];
    std::snprintf(overlay, sizeof overlay, "noise %.3g %% (log scale)", 100.0 * relativeError(stats.errorHistory.back().second));
    // An explicit width: PlotLines in ImGui 1.86 does not take -1 to mean "to the right edge".
    ImGui::PlotLines("##error", logErrors.data(), static_cast<int>(logErrors.size()), 0, overlay, FLT_MAX, FLT_MAX,
                     ImVec2(ImGui::GetContentRegionAvail().x, kPlotHeight));
    itemTooltip("log10 of the estimated noise (relative error without bias), about once a second of rendering while the\n"
                "estimate is reliable");
}

void drawViewStats(const ViewerSession& session, ViewerSession::Side side, double frameSeconds) {
    const ViewerModel& model = session.model();
    const RenderSettings& settings = session.settings(side);
    ViewerSession::ViewStats stats = session.stats(side);
    ImGui::TextUnformatted(
        viewHeading(session.comparing(), side == ViewerSession::Side::Left, settings.integrator, settings.sampler).c_str());
    if (model.targetSamples > 0) {
        ImGui::Text("%d / %d spp%s", stats.samples, model.targetSamples,
                    stats.samples >= model.targetSamples ? "  (target reached)" : "");
    } else {
        ImGui::Text("%d spp", stats.samples);
    }
    glm::ivec2 size = session.renderSize();
    ImGui::Text("%d x %d pixels, %.1f ms/frame", size.x, size.y, frameSeconds * 1e3);
    // Adaptive sampling: at its last check, the share of pixels done and each pixel's own count.
    if (stats.adaptive) {
        const ViewerSession::ViewStats::Adaptive& adaptive = *stats.adaptive;
        ImGui::Text("adaptive (target %.3g%%): %.1f%% of pixels done", 100.0 * adaptive.targetError,
                    100.0 * adaptive.samples.stoppedShare);
        ImGui::Text("spp min / mean / max: %d / %.1f / %d", adaptive.samples.min, adaptive.samples.mean, adaptive.samples.max);
        itemTooltip(("each pixel's own sample count at the last check (the checks come at " +
                     adaptiveCheckSchedule(kAdaptiveMinSamples, kAdaptiveCheckGrowth) +
                     "); a pixel done takes no more samples until the render restarts").c_str());
        if (!adaptive.note.empty()) noteText(adaptive.note);
    }
    ImGui::Text("%.2f M samples/s, %.1f s rendering", stats.samplesPerSecond * 1e-6, stats.renderSeconds);
    // The estimate and the true error are the same quantity (relative MSE as ErrorMetrics.h defines
    // it), shown the same way, so with a reference loaded the two lines can be compared directly.
    // Both come from the raw accumulation (readStatistics): labelled so, since the image shown may
    // be the denoised one.
    if (stats.denoised)
        noteText(stats.denoisedSamples > 0 ? "shown: denoised, of " + std::to_string(stats.denoisedSamples) + " spp (biased)"
                                           : std::string("shown: raw until the first denoising ends"));
    // Each figure with the spp it was measured at (about once a second), and the estimate named
    // for what it sees: noise, not bias (PanelText.h).
    std::string estimate = "raw: estimated " + noiseEstimateText(stats.error, stats.errorSamples);
    if (stats.error.reliable) {
        char relMse[32];
        std::snprintf(relMse, sizeof relMse, " (relMSE %.3g)", stats.error.relativeMse);
        estimate += relMse;
    } else {
        estimate += "  (not yet reliable)";
    }
    ImGui::TextUnformatted(estimate.c_str());
    if (stats.error.reliable)
        itemTooltip("estimated from the render itself: sqrt of the relative MSE against the image it converges to,\n"
                    "mean of (x - converged)^2 / (converged^2 + 0.01); each pixel's change since an earlier read-back,\n"
                    "over the brightness of the smallest neighbourhood that knows it (docs/viewer.md).\n"
                    "It measures noise only: a view that leaves light out (direct only, a low depth) converges to\n"
                    "the wrong image with a small estimate. Only a reference shows that bias");
    else
        itemTooltip((std::string("no estimate yet: ") + stats.error.unreliableReason).c_str());
    // One line of a true error: "raw vs reference: true error 9.2% (at 16 spp), relMSE ..., RMSE ...".
    auto trueErrorLine = [&stats](const char* image, const ErrorMetrics& e) {
        ImGui::Text("%s vs reference: %s, relMSE %.3g, RMSE %.3g", image, trueErrorText(e, stats.errorSamples).c_str(),
                    e.relativeMse, e.rmse);
    };
    if (stats.trueError) {
        const ErrorMetrics& e = *stats.trueError;
        trueErrorLine("raw", e);
        itemTooltip("the true error against the loaded reference image: sqrt of the relative MSE,\n"
                    "mean of (x - ref)^2 / (ref^2 + 0.01); includes the reference's own noise");
        ImGui::Text("bias %+.2g %+.2g %+.2g", e.meanBias.r, e.meanBias.g, e.meanBias.b);
        itemTooltip("mean of the image minus mean of the reference, per channel: what more samples cannot remove");
        if (stats.denoisedTrueError) {
            trueErrorLine("denoised", *stats.denoisedTrueError);
            itemTooltip("the same measure of the denoised image: lower than the raw one while the filter takes out more\n"
                        "noise than the bias it adds; it stops falling where the bias dominates");
        }
        std::vector<float> logs;
        for (const auto& [seconds, relMse] : stats.trueErrorHistory)
            if (relMse > 0.0f) logs.push_back(std::log10(float(relativeError(relMse))));
        if (logs.size() >= 2) {
            char overlay[48];
            std::snprintf(overlay, sizeof overlay, "true %.3g %% (log scale)", 100.0 * relativeError(stats.trueErrorHistory.back().second));
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
    itemTooltip("a .pfm or .exr of this scene at the render's size (e.g. ptview render SCENE --spp 4096 --size WxH --out ref.pfm):\n"
                "the panel then shows the true error against it");
    if (model.reference) {
        ImGui::TextDisabled("reference: %s", printableText(model.referencePath.filename().string()).c_str());
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
