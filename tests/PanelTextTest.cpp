// What the panels and the image say where it depends on numbers and state (issue 37: "1 programs
// compiled", "left: full, sobol" with no split view to be the left of, an error figure printed
// beside a spp it was not measured at, an estimate of noise called "error", feedback that only
// the sidebar gave).
#include <ptview/window/PanelText.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace ptview {
namespace {

TEST(PanelText, OneOfAThingIsSingular) {
    EXPECT_EQ(countOf(1, "program"), "1 program");
    EXPECT_EQ(countOf(0, "program"), "0 programs");
    EXPECT_EQ(countOf(3, "program"), "3 programs");
}

// The tooltips that explain adaptive sampling say when it checks from AdaptiveSampler's constants,
// not from a copy of them that a change of the constants leaves behind (they said 1.25x after the
// growth became 1.1x).
TEST(PanelText, TheAdaptiveCheckScheduleIsWordedFromItsConstants) {
    EXPECT_EQ(adaptiveCheckSchedule(64, 1.1), "32 spp, then each 1.1x the last; no pixel stops before 64");
    EXPECT_EQ(adaptiveCheckSchedule(16, 1.25), "8 spp, then each 1.25x the last; no pixel stops before 16");
}

TEST(PanelText, AViewNamesItsSideOnlyInTheSplitView) {
    EXPECT_EQ(viewHeading(false, true, Integrator::Full, SamplerMode::Sobol), "full, sobol");
    EXPECT_EQ(viewHeading(true, true, Integrator::Full, SamplerMode::Sobol), "left: full, sobol");
    EXPECT_EQ(viewHeading(true, false, Integrator::Mis, SamplerMode::Random), "right: mis, random");
}

// The sidebar's label column is as wide as "samples/frame" (Viewer.cpp), in ImGui's monospaced
// default font: a longer label beside a slider or a combo is cut ("aperture radiu", issue 37).
// ImGui does not wrap a tooltip: every one goes through wrappedTooltip (PanelWidgets.h), which
// does, so none is cut at the window's edge (the Trace paths button's was, issue 37).
TEST(PanelText, EveryTooltipWraps) {
    int wrapped = 0;
    for (const auto& entry : std::filesystem::directory_iterator(PTVIEW_ASSETS_DIR "/../app/window")) {
        std::ifstream in(entry.path());
        std::string source((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const bool widgets = entry.path().filename() == "PanelWidgets.h";
        for (size_t at = source.find("SetTooltip("); at != std::string::npos; at = source.find("SetTooltip(", at + 1))
            ADD_FAILURE() << entry.path().filename() << ": an unwrapped ImGui::SetTooltip; use wrappedTooltip or itemTooltip";
        for (size_t at = source.find("Tooltip("); at != std::string::npos; at = source.find("Tooltip(", at + 1))
            wrapped += widgets ? 0 : 1;
    }
    EXPECT_GT(wrapped, 50) << "the tooltips were found";
}

TEST(PanelText, EveryWidgetLabelFitsTheSidebarsLabelColumn) {
    const std::size_t column = std::string("samples/frame").size();
    const std::regex widget(R"((?:Slider\w*|Drag\w*|Combo|Input\w*|ColorEdit\d|enumCombo)\(\s*"([^"#]*)(?:##[^"]*)?")");
    int labels = 0;
    for (const auto& entry : std::filesystem::directory_iterator(PTVIEW_ASSETS_DIR "/../app/window")) {
        if (entry.path().extension() != ".cpp") continue;
        std::ifstream in(entry.path());
        std::stringstream text;
        text << in.rdbuf();
        const std::string source = text.str();
        for (std::sregex_iterator it(source.begin(), source.end(), widget), end; it != end; ++it) {
            const std::string label = (*it)[1];
            ++labels;
            EXPECT_LE(label.size(), column) << entry.path().filename() << ": \"" << label << "\" is cut in the sidebar";
        }
    }
    EXPECT_GT(labels, 30) << "the widgets were found";
}

ErrorEstimate reliableEstimate(double relativeErrorFraction) {
    ErrorEstimate estimate;
    estimate.reliable = true;
    estimate.relativeMse = relativeErrorFraction * relativeErrorFraction;
    return estimate;
}

ErrorMetrics trueError(double relativeErrorFraction) {
    ErrorMetrics metrics;
    metrics.relativeMse = relativeErrorFraction * relativeErrorFraction;
    return metrics;
}

// The error is measured about once a second: "16 spp ... relative error 29.6%" was the 2-spp value.
TEST(PanelText, AnErrorFigureSaysTheSppItWasMeasuredAt) {
    EXPECT_EQ(noiseEstimateText(reliableEstimate(0.092), 16), "noise ~9.2% (at 16 spp)");
    EXPECT_EQ(trueErrorText(trueError(0.296), 2), "true error 29.6% (at 2 spp)");
    EXPECT_EQ(noiseEstimateText(ErrorEstimate{}, 16), "noise -") << "no figure, no count";
}

// Direct lighting alone showed "error ~0.54%" beside full's "~11.25%" though it lacks all the
// indirect light: the estimate sees noise, not bias, so it is called noise, and with a reference
// the true error stands beside it.
TEST(PanelText, TheSplitViewLabelCallsTheEstimateNoiseAndShowsTheTrueErrorBesideIt) {
    EXPECT_EQ(splitLabelNumbers(16, 1.3, reliableEstimate(0.0054), nullptr, 16), "16 spp, 1.3 s, raw noise ~0.54% (at 16 spp)");
    ErrorMetrics reference = trueError(0.278);
    EXPECT_EQ(splitLabelNumbers(20, 1.3, reliableEstimate(0.0054), &reference, 16),
              "20 spp, 1.3 s, raw noise ~0.54% (at 16 spp), true error 27.8% (at 16 spp)");
}

// After Tab hides the sidebar, the image says what it shows when that is not the plain render.
TEST(PanelText, TheImageIsLabelledWhenItIsNotThePlainRender) {
    RenderSettings settings;
    EXPECT_EQ(imageContentLabel(settings, false, 0), "");
    EXPECT_EQ(imageContentLabel(settings, true, 16), "denoised");
    EXPECT_EQ(imageContentLabel(settings, true, 0), "raw, denoising")
        << "until the first denoised image of a render exists, the raw one is shown and not called denoised";
    settings.lightPaths = LightPaths::Direct;
    EXPECT_EQ(imageContentLabel(settings, false, 0), "light paths: direct only");
    EXPECT_EQ(imageContentLabel(settings, true, 4), "light paths: direct only, denoised");
    settings.lightPaths = LightPaths::Exactly;
    settings.lightPathBounces = 2;
    EXPECT_EQ(imageContentLabel(settings, false, 0), "light paths: exactly 2 bounces");
    settings.lightPaths = LightPaths::AtMost;
    settings.lightPathBounces = 1;
    EXPECT_EQ(imageContentLabel(settings, false, 0), "light paths: at most 1 bounce");
    settings.debugView = DebugView::Normals;
    EXPECT_EQ(imageContentLabel(settings, false, 0), "view: normals") << "a debug view replaces the radiance";
}

// A reload error sat below the fold of the sidebar: the title says the last file did not apply,
// and clears with the error (which a successful reload clears).
TEST(PanelText, TheTitleSaysWhenTheLastSceneOrShaderFileDidNotApply) {
    const std::string dash = " \xE2\x80\x94 ";
    EXPECT_EQ(windowTitle("dir/cornell.json", false, "", ""), "ptview" + dash + "cornell.json");
    EXPECT_EQ(windowTitle("dir/cornell.json", true, "", ""), "ptview" + dash + "cornell.json *");
    EXPECT_EQ(windowTitle("dir/cornell.json", true, "cornell.json: /shapes/0: no such material", ""),
              "ptview" + dash + "cornell.json *" + dash + "load failed: see Scene panel");
    EXPECT_EQ(windowTitle("", false, "", "pathtrace.frag:12: syntax error"),
              "ptview" + dash + "untitled" + dash + "shader reload failed: see Render panel");
    EXPECT_EQ(reloadFailureNote("", ""), "");
    EXPECT_EQ(reloadFailureNote("x", "y"), "scene not applied: see Scene panel\nshader not applied: see Render panel");
}

// F12 confirmed only inside the Render panel: the image says which files it wrote.
TEST(PanelText, AScreenshotNoticeNamesTheFilesWritten) {
    std::vector<std::filesystem::path> files = {"screenshots/cornell-1.png", "screenshots/cornell-1.pfm",
                                                "screenshots/cornell-1.exr"};
    EXPECT_EQ(screenshotNotice(files), "saved screenshots/cornell-1.png, cornell-1.pfm, cornell-1.exr");
}

} // namespace
} // namespace ptview
