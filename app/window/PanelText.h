#pragma once
// Words the panels show that depend on numbers and state, as plain functions (no ImGui), so a
// test can read what the window would say.

#include <ptview/metrics/ErrorEstimate.h>
#include <ptview/metrics/ErrorMetrics.h>
#include <ptview/settings/DebugView.h>
#include <ptview/settings/Integrator.h>
#include <ptview/settings/LightPaths.h>
#include <ptview/settings/RenderSettings.h>
#include <ptview/settings/SamplerMode.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace ptview {

// "1 program", "2 programs": the count with its noun, singular for one.
inline std::string countOf(int count, const std::string& noun) {
    return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

// The heading of a view's statistics: which side it is only when there are two ("left: full,
// sobol"), else just the integrator and sampler.
inline std::string viewHeading(bool comparing, bool leftSide, Integrator integrator, SamplerMode sampler) {
    std::string heading = std::string(integratorName(integrator)) + ", " + samplerModeName(sampler);
    return comparing ? std::string(leftSide ? "left: " : "right: ") + heading : heading;
}

// When adaptive sampling reads the image back, for the tooltips that explain it: "32 spp, then each
// 1.1x the last; no pixel stops before 64", from AdaptiveSampler's constants (the first check only
// takes the snapshot the next one compares with).
inline std::string adaptiveCheckSchedule(int minSamples, double checkGrowth) {
    char text[96];
    std::snprintf(text, sizeof text, "%d spp, then each %gx the last; no pixel stops before %d", (minSamples + 1) / 2,
                  checkGrowth, minSamples);
    return text;
}

// A percentage as the panels print it: three significant digits ("9.2%", "0.537%").
inline std::string percentText(double fraction) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g%%", 100.0 * fraction);
    return text;
}

// The error figures are measured about once a second (ViewerSession::updateErrorEstimate), so
// beside a spp count that moves every frame each says the count it was measured at: "(at 16 spp)".
inline std::string measuredAt(int samples) { return "(at " + std::to_string(samples) + " spp)"; }

// The estimate compares the render with itself, so it sees noise and never bias (a view that
// leaves out light converges, quietly, to the wrong image): named "noise", never "error".
// "noise ~9.2% (at 16 spp)", or a dash until it is reliable.
inline std::string noiseEstimateText(const ErrorEstimate& estimate, int atSamples) {
    if (!estimate.reliable) return "noise -"; // ImGui's default font has no em dash
    return "noise ~" + percentText(relativeError(estimate.relativeMse)) + " " + measuredAt(atSamples);
}

// Against a reference: bias and noise together. "true error 27.8% (at 16 spp)".
inline std::string trueErrorText(const ErrorMetrics& error, int atSamples) {
    return "true error " + percentText(relativeError(error.relativeMse)) + " " + measuredAt(atSamples);
}

// The second line of a split view's label: "16 spp, 1.2 s, raw noise ~0.54% (at 16 spp)", and
// with a reference ", true error 27.8%" (measured at the same count), which is what tells a view
// that misses light from one that is merely converged.
inline std::string splitLabelNumbers(int samples, double seconds, const ErrorEstimate& estimate,
                                     const ErrorMetrics* trueError, int errorSamples) {
    char head[64];
    std::snprintf(head, sizeof head, "%d spp, %.1f s, raw ", samples, seconds);
    std::string text = head + noiseEstimateText(estimate, errorSamples);
    if (trueError) text += ", " + trueErrorText(*trueError, errorSamples);
    return text;
}

// What the image shows when it is not the plain radiance, so it can be told with the sidebar
// hidden: "light paths: direct only", "light paths: exactly 2 bounces", "view: normals",
// "denoised", joined by ", "; empty for the plain render. A debug view replaces the radiance, so
// the light paths (and the denoiser, which a debug view never gets) are not named with it. With
// the denoiser on (`denoised`) but no denoised image yet (`denoisedSamples` 0: the first filtering
// of this render is under way) the image is still the raw one, and the label says so.
inline std::string imageContentLabel(const RenderSettings& settings, bool denoised, int denoisedSamples) {
    if (settings.debugView != DebugView::Radiance) return std::string("view: ") + debugViewName(settings.debugView);
    std::vector<std::string> parts;
    if (settings.lightPaths != LightPaths::All) {
        // The Render panel's label of the view ("Exactly k bounces", "Direct only"), with k filled in.
        std::string view = lightPathsNames().entry(settings.lightPaths).label;
        view[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(view[0])));
        const std::string k = "k bounces";
        if (lightPathsUseBounces(settings.lightPaths) && view.find(k) != std::string::npos)
            view.replace(view.find(k), k.size(), countOf(settings.lightPathBounces, "bounce"));
        parts.push_back("light paths: " + view);
    }
    if (denoised) parts.push_back(denoisedSamples > 0 ? "denoised" : "raw, denoising");
    std::string label;
    for (const std::string& part : parts) label += (label.empty() ? "" : ", ") + part;
    return label;
}

// "ptview \u2014 cornell.json *", and while the last scene or shader file did not apply (the
// panel that says why may be closed or below the fold) "... \u2014 load failed: see Scene panel".
// The errors clear when a load or reload succeeds (ViewerSession), and the title with them.
inline std::string windowTitle(const std::filesystem::path& sceneFile, bool unsavedEdits, const std::string& sceneError,
                               const std::string& shaderError) {
    const char* dash = " \xE2\x80\x94 ";
    std::string title = "ptview" + std::string(dash) + (sceneFile.empty() ? std::string("untitled") : sceneFile.filename().string());
    if (unsavedEdits) title += " *";
    if (!sceneError.empty()) title += dash + std::string("load failed: see Scene panel");
    if (!shaderError.empty()) title += dash + std::string("shader reload failed: see Render panel");
    return title;
}

// The same on the image, where a full-screen window has no title bar: "" when all applied.
inline std::string reloadFailureNote(const std::string& sceneError, const std::string& shaderError) {
    std::string note;
    if (!sceneError.empty()) note = "scene not applied: see Scene panel";
    if (!shaderError.empty()) note += std::string(note.empty() ? "" : "\n") + "shader not applied: see Render panel";
    return note;
}

// What F12 says on the image, briefly: "saved screenshots/cornell-1.png, cornell-1.pfm, cornell-1.exr"
// (the first file with its folder, the rest by name: they sit beside it).
inline std::string screenshotNotice(const std::vector<std::filesystem::path>& files) {
    std::string notice = "saved";
    for (size_t i = 0; i < files.size(); ++i)
        notice += (i == 0 ? " " : ", ") + (i == 0 ? files[i].string() : files[i].filename().string());
    return notice;
}

// How long a notice on the image stays.
constexpr double kImageNoticeSeconds = 4.0;

} // namespace ptview
