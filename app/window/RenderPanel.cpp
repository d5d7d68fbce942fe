// The Render panel: how the image is computed and shown, the split view, and screenshots.
#include <ptview/window/PanelText.h>
#include <ptview/window/Panels.h>

#include <ptview/window/PanelWidgets.h>
#include <ptview/io/PrintableText.h>
#include <ptview/settings/SettingRanges.h>
#include <ptview/tracer/AdaptiveSampler.h>

#include <imgui.h>

#include <algorithm>
#include <exception>
#include <optional>

namespace ptview {
namespace {

// Grid and stratified are meant to stop at a complete pattern; say where this one stops.
void patternNote(const ViewerModel& model) {
    bool anyPattern = needsPatternTarget(model.settings.sampler) ||
                      (model.compare.enabled && needsPatternTarget(model.compare.right.sampler));
    if (!anyPattern) return;
    if (model.targetSamples > 0)
        noteText("the pattern is complete at the target, " + std::to_string(model.targetSamples) + " spp");
    else
        noteText("no target spp: the pattern is incomplete (patchy) until " +
                 std::to_string(model.settings.sampleBudget) + " spp");
}

// An integer setting's slider over the span its range gives the panels (SettingRanges.h); a typed
// value (Ctrl+click) stays in that span.
void settingSlider(const char* label, int& value, const NumberRange& range) {
    ImGui::SliderInt(label, &value, static_cast<int>(range.panelLo), static_cast<int>(range.panelHi), "%d",
                     ImGuiSliderFlags_AlwaysClamp);
}

// Firefly control: off (unbiased) or a largest component per path vertex's contribution.
void clampControls(RenderSettings& settings) {
    constexpr float kFirstClamp = 10.0f; // what turning it on starts from: a few times a lit white wall
    bool clamped = settings.radianceClamp.has_value();
    if (ImGui::Checkbox("clamp", &clamped)) settings.radianceClamp = clamped ? std::optional<float>(kFirstClamp) : std::nullopt;
    itemTooltip("firefly control, BIASED: each contribution of a path vertex (throughput x emission or x a light\n"
                "sample) is scaled down to this largest component; the light cut off is lost, so the image\n"
                "converges to a darker one than the true image");
    if (!settings.radianceClamp) return;
    ImGui::SameLine();
    float value = *settings.radianceClamp;
    if (ImGui::SliderFloat("##clamp value", &value, settingRanges::kRadianceClamp.panelLo, settingRanges::kRadianceClamp.panelHi, "%.3g", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
        settings.radianceClamp = value;
}

// The denoiser's controls (docs/denoising.md): none of them restarts the accumulation.
void denoiseControls(ViewerModel& model) {
    ImGui::Checkbox("Denoise (N)", &model.denoise.enabled);
    itemTooltip("show a denoised copy of the render: a filter (a-trous; or, slower, regression) guided by albedo,\n"
                "normal, depth and each pixel's variance. BIASED: it borrows light from neighbours, so fine detail and\n"
                "soft shadows blur; the bias falls as the noise does. The samples still accumulate raw underneath\n"
                "(Stats' errors are of the raw image). Filtered in bands of rows over a few frames (docs/viewer.md)");
    if (model.settings.debugView != DebugView::Radiance) noteText("the debug view is shown raw: it has no noise to take out");
    if (!model.denoise.enabled && !(model.compare.enabled && model.compare.sides == CompareSides::RawAndDenoised) &&
        !(model.compare.enabled && model.compare.rightDenoised))
        return;
    const NumberRange& strength = settingRanges::kDenoiseStrength;
    ImGui::SliderFloat("strength", &model.denoise.strength, static_cast<float>(strength.panelLo),
                       static_cast<float>(strength.panelHi), "%.3g", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    itemTooltip(strength.description);
    enumCombo("filter", denoiseAlgorithmNames(), model.denoise.algorithm); // its tooltip: the entry's description
    if (model.denoise.algorithm == DenoiseAlgorithm::Atrous) {
        settingSlider("iterations", model.denoise.iterations, settingRanges::kDenoiseIterations);
        itemTooltip(settingRanges::kDenoiseIterations.description);
    }
    noteText("biased: it borrows light from neighbours; the bias falls as the noise does");
}

// What the split view's halves show: two renders, or the main one raw and denoised.
void compareSidesControls(ViewerModel& model) {
    int sides = static_cast<int>(model.compare.sides);
    ImGui::RadioButton("two renders", &sides, static_cast<int>(CompareSides::TwoRenders));
    itemTooltip("left: the settings above; right: the settings below, each its own render");
    ImGui::SameLine();
    ImGui::RadioButton("raw | denoised", &sides, static_cast<int>(CompareSides::RawAndDenoised));
    itemTooltip("one render, the left settings': its raw mean left of the divider, denoised right of it\n"
                "(with the strength and iterations above)");
    ImGui::SameLine();
    ImGui::RadioButton("image | view", &sides, static_cast<int>(CompareSides::ImageAndView));
    itemTooltip("one render, the left settings': the image left of the divider, the view chosen above\n"
                "(error map, estimated error, difference) right of it");
    model.compare.sides = static_cast<CompareSides>(sides);
}

// An OpenColorIO config typed or loaded with --ocio-config, its displays and their views.
void ocioControls(ViewerSession& session, PanelState& state) {
    ViewerModel& model = session.model();
    ImGui::PushID("ocio");
    ImGui::TextUnformatted("OpenColorIO config");
    itemTooltip("a config.ocio (Blender's, ACES, your own): its displays and views become the tone mapper \"ocio\"");
    if (pathField("Load", state.ocioConfigInput)) session.setOcioView({state.ocioConfigInput, "", ""});
    if (!model.ocio.config.empty()) {
        ImGui::TextWrapped("%s", printableText(model.ocio.config).c_str());
        const OcioRequest current = model.ocio;
        if (ImGui::BeginCombo("display", current.display.c_str())) {
            for (const OcioDisplayViews& display : session.ocioDisplays())
                if (ImGui::Selectable(display.display.c_str(), display.display == current.display))
                    session.setOcioView({current.config, display.display, ""});
            ImGui::EndCombo();
        }
        if (ImGui::BeginCombo("view", current.view.c_str())) {
            for (const OcioDisplayViews& display : session.ocioDisplays())
                if (display.display == current.display)
                    for (const std::string& view : display.views)
                        if (ImGui::Selectable(view.c_str(), view == current.view)) session.setOcioView({current.config, current.display, view});
            ImGui::EndCombo();
        }
        if (ImGui::Button("Remove config")) session.setOcioView({});
    }
    if (!model.ocioError.empty()) errorText(model.ocioError);
    ImGui::PopID();
}

// Adaptive sampling of the main view (ViewerModel::targetErrorOn): a checkbox, the target in
// percent, and why it stopped once it has.
void targetErrorControls(ViewerSession& session) {
    ViewerModel& model = session.model();
    ImGui::Checkbox("stop at error", &model.targetErrorOn);
    itemTooltip((std::string("adaptive sampling: each pixel stops once the estimated error of its neighbourhood reaches the target, "
                             "and the render stops when the image's estimate does (or every pixel stopped), as "
                             "`ptview render --noise-threshold` does. The checks read the image back at fixed sample counts (") +
                 adaptiveCheckSchedule(kAdaptiveMinSamples, kAdaptiveCheckGrowth) +
                 "); changing the target restarts. The \"samples per pixel\" view shows where the samples went").c_str());
    if (!model.targetErrorOn) return;
    ImGui::SameLine();
    float percent = 100.0f * model.targetError;
    const NumberRange& range = settingRanges::kNoiseThreshold;
    // 0.5% .. 20%: below, a viewer waits minutes for the checks; above, the image is plainly noisy.
    if (ImGui::SliderFloat("##target error", &percent, 0.5f, 100.0f * range.panelHi, "%.2g%%", ImGuiSliderFlags_Logarithmic))
        model.targetError = std::clamp(percent / 100.0f, 0.005f, range.panelHi);
    ViewerSession::ViewStats stats = session.stats(ViewerSession::Side::Left);
    if (stats.adaptive && !stats.adaptive->note.empty()) noteText(stats.adaptive->note);
}

} // namespace

void saveScreenshots(ViewerSession& session, PanelState& state) {
    try {
        std::vector<std::filesystem::path> files = session.saveScreenshots("screenshots");
        // Made printable here (PrintableText.h), line by line, since the panel and a script's
        // stdout both show it: the files are named after the scene, which may be a stranger's.
        state.screenshotMessage = "saved";
        for (const std::filesystem::path& file : files) state.screenshotMessage += "\n" + printableText(file.string());
        state.screenshotFailed = false;
        state.showImageNotice(printableText(screenshotNotice(files)), false);
    } catch (const std::exception& e) {
        state.screenshotMessage = printableText(std::string("screenshot not saved: ") + e.what());
        state.screenshotFailed = true;
        state.showImageNotice(state.screenshotMessage, true);
    }
}

void drawLightPathControls(ViewerModel& model) {
    RenderSettings& settings = model.settings;
    enumCombo("view", debugViewNames(), settings.debugView);
    itemTooltip("radiance: the render; normals and albedo: the first surface the camera sees (debug views)");
    ImGui::Checkbox("highlight NaN/Inf (magenta)", &model.display.highlightNonFinite);
    // The light-path explorer: the same paths, only a part of what they carry added up.
    enumCombo("light paths", lightPathsNames(), settings.lightPaths);
    if (lightPathsUseBounces(settings.lightPaths)) settingSlider("bounces k", settings.lightPathBounces, settingRanges::kLightPathBounces);
}

void drawCompareControls(ViewerModel& model) {
    ImGui::Checkbox("Compare (split view)", &model.compare.enabled);
    itemTooltip("two renders of the same scene side by side; drag the white divider (key C)");
    if (model.compare.enabled) compareSidesControls(model);
    if (model.compare.enabled && model.compare.sides == CompareSides::TwoRenders) {
        ImGui::TextDisabled("right side (above: the left side):");
        enumCombo("integrator##right", integratorNames(), model.compare.right.integrator);
        enumCombo("sampler##right", samplerModeNames(), model.compare.right.sampler);
        settingSlider("MAX_DEPTH##right", model.compare.right.maxDepth, settingRanges::kMaxDepth);
        ImGui::Checkbox("denoise##right", &model.compare.rightDenoised);
        itemTooltip("show the right render denoised (strength and iterations above); the left follows Denoise above");
        ImGui::Checkbox("equal time", &model.compare.equalTime);
        itemTooltip("on: both sides get the same GPU time (a cheaper method gets more samples);\n"
                "off: both get the same number of samples per pixel");
    }
}

void drawRenderPanel(ViewerSession& session, PanelState& state) {
    ViewerModel& model = session.model();
    RenderSettings& settings = model.settings;
    // Short labels, so the combos have room for whole entries; in compare mode these are the
    // left side's, and the right side's follow a "right side" line below.
    enumCombo("integrator", integratorNames(), settings.integrator);
    settingSlider("MAX_DEPTH", settings.maxDepth, settingRanges::kMaxDepth);
    itemTooltip("bounces after the camera ray; 0 shows only what the camera sees directly");
    clampControls(settings);
    enumCombo("sampler", samplerModeNames(), settings.sampler);
    patternNote(model);

    int perFrame = model.maxSamplesPerFrame;
    // 0 is "auto", below the range (as the script's word is).
    if (ImGui::SliderInt("samples/frame", &perFrame, 0, static_cast<int>(settingRanges::kSamplesPerFrame.panelHi),
                         perFrame == 0 ? "auto" : "%d"))
        model.maxSamplesPerFrame = perFrame;
    itemTooltip("most samples per pixel per displayed frame; auto: as many as fit in 30 ms of GPU time.\n"
            "A slow GPU renders a sample in tiles over several frames, so the window stays responsive.");
    ImGui::SliderInt("target spp", &model.targetSamples, static_cast<int>(settingRanges::kTargetSamples.panelLo),
                     static_cast<int>(settingRanges::kTargetSamples.panelHi), model.targetSamples == 0 ? "none" : "%d",
                     ImGuiSliderFlags_Logarithmic);
    itemTooltip("stop accumulating at this many samples per pixel (grid and stratified samplers are fully\n"
            "stratified there); 0: never stop");
    targetErrorControls(session);
    if (ImGui::Button(model.paused ? "Resume" : "Pause")) model.paused = !model.paused;
    ImGui::SameLine();
    if (ImGui::Button("Restart")) model.pendingChanges |= ViewerModel::kRestart;
    // The backend, where there is a choice; the program is specialized to the scene either way.
    ImGui::BeginDisabled(!PathTracer::computeSupported());
    enumCombo("backend", backendNames(), model.backend);
    ImGui::EndDisabled();
    itemTooltip("fragment: a full-screen triangle (OpenGL 4.1); compute: a dispatch (OpenGL 4.3), which uses all of a\n"
                "data-centre GPU's cores. At start the viewer took the one measured faster on this scene and device\n"
                "(compute only where clearly faster), remembered per device and program.");
    if (!model.backendChoice.empty()) noteText("auto: " + model.backendChoice);
    const PathTracer& tracer = session.tracer(ViewerSession::Side::Left);
    ImGui::TextDisabled("%s compiled (hover: this scene's features)", countOf(tracer.programsCompiled(), "program").c_str());
    if (ImGui::IsItemHovered()) wrappedTooltip(tracer.features().describe());
    ImGui::SliderFloat("resolution", &model.resolutionScale, settingRanges::kResolutionScale.panelLo,
                       settingRanges::kResolutionScale.panelHi, "%.3f x");
    itemTooltip("render at this multiple of the window's pixels: below 1 faster and coarser, above 1 supersampled");

    if (state.detached.drawInSidebar(DetachableSection::LightPaths)) drawLightPathControls(model);

    ImGui::Separator();
    ImGui::SliderFloat("exposure", &model.display.exposureStops, settingRanges::kExposure.panelLo, settingRanges::kExposure.panelHi,
                       "%+.1f stops", ImGuiSliderFlags_AlwaysClamp);
    if (enumCombo("tone mapper", toneMapperNames(), model.display.toneMapper) && model.display.toneMapper == ToneMapper::Ocio &&
        model.ocio.config.empty()) {
        model.display.toneMapper = ToneMapper::Reinhard; // nothing to show yet
        model.ocioError = "load an OpenColorIO config first (below)";
    }
    ImGui::BeginDisabled(model.display.toneMapper == ToneMapper::Ocio);
    enumCombo("encoding", displayTransferNames(), model.display.transfer); // the display transfer curve
    ImGui::EndDisabled();
    itemTooltip("how the tone-mapped values are encoded for the screen and a saved PNG: the exact sRGB curve,\n"
                "or gamma 2.2 as ptview wrote images before (a file opened with --from keeps its own);\n"
                "an OpenColorIO view encodes for its display itself");
    ocioControls(session, state);
    drawViewControls(session, state);

    ImGui::Separator();
    denoiseControls(model);

    ImGui::Separator();
    if (state.detached.drawInSidebar(DetachableSection::Compare)) drawCompareControls(model);

    ImGui::Separator();
    if (ImGui::Button("Screenshot (F12)")) saveScreenshots(session, state);
    itemTooltip("tone-mapped PNG, linear PFM and EXR of the image (each side in compare mode) into screenshots/");
    if (!state.screenshotMessage.empty()) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextColored(state.screenshotFailed ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f) : ImVec4(0.5f, 0.9f, 0.5f, 1.0f),
                           "%s", state.screenshotMessage.c_str());
        ImGui::PopTextWrapPos();
    }
    if (!model.shaderError.empty()) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "Shader reload failed (the last good shaders still run):\n%s",
                           model.shaderError.c_str());
        ImGui::PopTextWrapPos();
    }
}

} // namespace ptview
