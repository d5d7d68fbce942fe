#include <ptview/window/ScriptRunner.h>

#include <ptview/model/CameraController.h>
#include <ptview/model/EditHistory.h>
#include <ptview/commands/CommandErrors.h>
#include <ptview/scene/MaterialInputs.h>
#include <ptview/scene/MaterialSchema.h>
#include <ptview/scene/MaterialTextures.h>
#include <ptview/window/MaterialsPanel.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/commands/OutputPath.h>
#include <ptview/commands/PathsJson.h>
#include <ptview/window/PanelText.h>
#include <ptview/io/PrintableText.h>
#include <ptview/io/ImageIO.h>
#include <ptview/scene/SceneRanges.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string_view>
#include <utility>
#include <cstdio>
#include <utility>

namespace ptview {
namespace {

// Long enough for a slow software rasterizer to reach a few hundred samples of a small image.
constexpr std::chrono::seconds kWaitTimeout{120};
constexpr std::chrono::seconds kReloadTimeout{10};
using Clock = std::chrono::steady_clock;

// The parser checked the names: the fallbacks are unreachable.
Integrator integratorNamed(const std::string& name) { return integratorNames().parse(name).value_or(Integrator::Naive); }
ToneMapper toneMapperNamed(const std::string& name) { return toneMapperNames().parse(name).value_or(ToneMapper::Reinhard); }
DisplayTransfer displayTransferNamed(const std::string& name) {
    return displayTransferNames().parse(name).value_or(DisplayTransfer::Srgb);
}

// Quoted for the status line: one line, quotes and backslashes escaped. Scene paths and errors
// may come from a file someone sent: its control characters are shown as escapes (PrintableText.h).
std::string quoted(const std::string& text) {
    std::string oneLine = text;
    std::replace(oneLine.begin(), oneLine.end(), '\n', ' ');
    std::string out = "\"";
    for (char c : printableText(oneLine)) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

std::string vectorText(const glm::vec3& v) {
    char text[96];
    std::snprintf(text, sizeof(text), "%.6g,%.6g,%.6g", v.x, v.y, v.z);
    return text;
}

std::string numberText(float value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.6g", static_cast<double>(value));
    return text;
}

// "materials, camera": the kinds of unsaved edits, joined with `separator`.
std::string joined(const std::vector<std::string>& words, const char* separator) {
    std::string text;
    for (const std::string& word : words) text += (text.empty() ? "" : separator) + word;
    return text;
}

void printStatus(const ViewerSession& session, const PanelState& panels) {
    const ViewerModel& model = session.model();
    ViewerSession::ViewStats left = session.stats(ViewerSession::Side::Left);
    const RenderSettings& settings = session.settings(ViewerSession::Side::Left);
    std::string line = "status spp=" + std::to_string(left.samples) + " size=" +
                       std::to_string(session.renderSize().x) + "x" + std::to_string(session.renderSize().y) +
                       " integrator=" + integratorName(settings.integrator) + " sampler=" +
                       samplerModeName(settings.sampler) + " depth=" + std::to_string(settings.maxDepth) +
                       " light-paths=" + lightPathsName(settings.lightPaths) +
                       (lightPathsUseBounces(settings.lightPaths) ? ":" + std::to_string(settings.lightPathBounces) : "") +
                       " target-spp=" + std::to_string(model.targetSamples) +
                       " backend=" + backendName(session.tracer(ViewerSession::Side::Left).backend()) +
                       " reloads=" + std::to_string(session.reloadCount()) + " eye=" + vectorText(model.scene.camera.eye) +
                       " aperture=" + numberText(model.scene.camera.apertureRadius) +
                       " focus=" + numberText(model.scene.camera.focusDistance) +
                       " clamp=" + (settings.radianceClamp ? numberText(*settings.radianceClamp) : std::string("off")) +
                       " compare=" +
                       (session.comparing() ? "on" : "off");
    // The image area the render is displayed in (it keeps its size through Tab or a resize), and
    // the low-resolution preview level on screen, if any (PathTracer::setPreviewEnabled).
    PixelRect area = session.imageArea();
    glm::ivec2 preview = session.tracer(ViewerSession::Side::Left).shownPreviewSize();
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, " render-seconds=%.3f", left.renderSeconds);
    line += seconds;
    // The first row of the full-size pass in progress: it moves even while spp waits for a slow pass.
    line += " pass-row=" + std::to_string(session.tracer(ViewerSession::Side::Left).nextRow());
    line += " area=" + std::to_string(area.size.x) + "x" + std::to_string(area.size.y) + " preview=" +
            (preview.x > 0 ? std::to_string(preview.x) + "x" + std::to_string(preview.y) : std::string("none"));
    if (session.comparing()) {
        const RenderSettings& right = session.settings(ViewerSession::Side::Right);
        line += " right-spp=" + std::to_string(session.stats(ViewerSession::Side::Right).samples) +
                " right-integrator=" + integratorName(right.integrator) + " right-sampler=" +
                samplerModeName(right.sampler);
    }
    if (left.trueError) {
        char text[64];
        std::snprintf(text, sizeof text, " true-rel-mse=%.6g", left.trueError->relativeMse);
        line += text;
    }
    // The denoiser: on or off, and the samples of the denoised image shown (it may lag spp).
    const DenoiseSettings& denoise = model.denoise;
    line += std::string(" denoise=") + (denoise.enabled ? "on" : "off") + " denoise-strength=" +
            numberText(denoise.strength) + " denoise-iterations=" + std::to_string(denoise.iterations) +
            " denoised-spp=" + std::to_string(left.denoised ? left.denoisedSamples : 0);
    // Adaptive sampling (docs/viewer.md, "Target error"): the target, then at the last check the
    // share of pixels stopped, each pixel's own sample counts and why it stopped ("" while it goes on).
    line += " target-error=" + (model.targetErrorOn ? numberText(model.targetError) : std::string("off"));
    if (left.adaptive) {
        const ViewerSession::ViewStats::Adaptive& adaptive = *left.adaptive;
        char text[160];
        std::snprintf(text, sizeof text, " adaptive-checks=%d stopped-share=%.6g spp-min=%d spp-mean=%.6g spp-max=%d",
                      adaptive.checks, adaptive.samples.stoppedShare, adaptive.samples.min, adaptive.samples.mean,
                      adaptive.samples.max);
        line += text;
        line += " adaptive-error=" + (adaptive.estimate.reliable ? numberText(float(relativeError(adaptive.estimate.relativeMse)))
                                                                  : std::string("unknown")) +
                " adaptive-stop=" + quoted(adaptive.note);
    }
    // The view, what it compares with and the zoom (docs/viewer.md, "Error and difference views").
    const PixelRect image = session.imageRect();
    line += std::string(" view=") + displayViewName(model.display.view) +
            " compare-image=" + quoted(model.compareImagePath.string()) + " view-problem=" +
            quoted(session.viewProblem(ViewerSession::Side::Left)) + " zoom=" +
            (model.zoom.fit() ? std::string("fit") : numberText(model.zoom.scale)) + " image-rect=" +
            std::to_string(image.origin.x) + "," + std::to_string(image.origin.y) + "," + std::to_string(image.size.x) + "x" +
            std::to_string(image.size.y);
    std::vector<std::string> edits = session.unsavedEdits();
    std::optional<UnsavedEditsPrompt::Action> asking = panels.unsavedEdits.pending();
    line += " edits=" + (edits.empty() ? std::string("none") : joined(edits, ",")) +
            " prompt=" + (asking ? actionName(*asking) : "none") + " save-target=" + quoted(session.saveTarget());
    // What Undo and Redo would do (the Edit section's buttons), and how many steps each way.
    const EditHistory& history = session.history();
    line += " undo=" + quoted(history.undoLabel()) + " redo=" + quoted(history.redoLabel()) +
            " undo-steps=" + std::to_string(history.undoSteps()) + " redo-steps=" + std::to_string(history.redoSteps());
    line += " scene=" + quoted(model.scene.path.string()) + " scene-error=" + quoted(model.sceneError) +
            " shader-error=" + quoted(model.shaderError);
    // What the window says beyond the sidebar: its title, the label on the image (empty for the
    // plain render) and the last notice drawn on it (PanelText.h decides all three).
    line += " title=" + quoted(windowTitle(model.fileScene.path, session.hasUnsavedEdits(), model.sceneError, model.shaderError)) +
            " image-label=" + quoted(imageContentLabel(settings, session.showsDenoised(ViewerSession::Side::Left),
                                                           session.tracer(ViewerSession::Side::Left).denoisedSampleCount())) +
            " notice=" + quoted(panels.imageNotice) + " popped-out=" + panels.detached.describe() +
            " ui-scale=" + numberText(panels.preferences.uiScale) +
            " high-contrast=" + (panels.preferences.highContrast ? "on" : "off");
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
}

} // namespace

// A script answers no questions: what it throws away it says on stderr.
void ScriptRunner::noteDiscardedEdits(const ScriptCommand& command, const std::vector<std::string>& edits) const {
    if (edits.empty()) return;
    printMessage(script_.path.string() + ":" + std::to_string(command.line) + ": " + command.verb +
               ": discarded unsaved edits (" + joined(edits, ", ") + ")");
}

void ScriptRunner::fail(const ScriptCommand& command, const std::string& reason) {
    printMessage(script_.path.string() + ":" + std::to_string(command.line) + ": " + command.verb + ": " + reason);
    exitCode_ = 2;
    quit_ = true;
}

std::optional<std::filesystem::path> ScriptRunner::takeWindowScreenshot() {
    std::optional<std::filesystem::path> path = std::move(windowScreenshot_);
    windowScreenshot_.reset();
    return path;
}

void ScriptRunner::step(ViewerSession& session, PanelState& panels) {
    while (!quit_ && next_ < script_.commands.size() && !windowScreenshot_) {
        const ScriptCommand& command = script_.commands[next_];
        if (!run(command, session, panels)) return;
        session.recordEdits(); // each command's edit is one undo step
        waiting_ = false;
        ++next_;
    }
}

// =====================================================================================
// One handler per command of the script table (ViewerScript.cpp)
// =====================================================================================

struct ScriptRunner::Step {
    Step(ScriptRunner& runner, const ScriptCommand& command, ViewerSession& session, PanelState& panels)
        : command(command), session(session), panels(panels), model(session.model()), scene(session.model().scene),
          word(command.words.empty() ? kNoWord : command.words[0]), runner_(runner) {}

    const ScriptCommand& command;
    ViewerSession& session;
    PanelState& panels;
    ViewerModel& model;
    Scene& scene;
    const std::string& word; // the first argument, or empty
    bool again = false;      // the command waits: run it again next frame

    // Ends the script: "FILE:LINE: verb: reason" on stderr, exit code 2.
    void fail(const std::string& reason) { runner_.fail(command, reason); }
    bool failed() const { return runner_.quit_; }
    void quit() { runner_.quit_ = true; }
    void noteDiscardedEdits(const std::vector<std::string>& edits) { runner_.noteDiscardedEdits(command, edits); }
    // "FILE:LINE: verb: text" on stderr; the script goes on.
    void note(const std::string& text) {
        printMessage(runner_.script_.path.string() + ":" + std::to_string(command.line) + ": " + command.verb + ": " + text);
    }
    void takeWindowScreenshot(const std::filesystem::path& path) { runner_.windowScreenshot_ = path; }
    long long framesDisplayed() const { return runner_.framesDisplayed_; }
    // What the command waits for, set on its first run (firstRun() is true once per command).
    bool firstRun() { return !std::exchange(runner_.waiting_, true); }
    Wait& wait() { return runner_.wait_; }

private:
    static inline const std::string kNoWord;
    ScriptRunner& runner_;
};

namespace {

using Step = ScriptRunner::Step;
using Handler = void (*)(Step&);

// ---- scene edits

void sceneEdited(Step& s) { s.model.pendingChanges |= ViewerModel::kSceneChanged; }

// set-material NAME.INPUT-texture PATH|none: what the Materials panel's Load and Remove do. A
// file that does not load fails the script (naming it); the material stays as it was.
void setMaterialTextureField(Step& s, Material& material) {
    for (const MaterialTextureInput& input : kMaterialTextureInputs) {
        if (s.command.field != std::string(input.name) + "-texture") continue;
        try {
            Material edited = material;
            if (!s.command.isWord(0, "none") && edited.type != MaterialType::Principled)
                edited = retypedMaterial(edited, MaterialType::Principled);
            setMaterialTexture(s.scene, edited, input, s.command.isWord(0, "none") ? std::filesystem::path() : std::filesystem::path(s.word));
            material = edited;
        } catch (const SceneError& error) {
            return s.fail(error.what());
        }
        // A texture where the program had none needs another program: upload the scene again.
        s.model.pendingChanges |= ViewerModel::kSceneChanged | ViewerModel::kMaterialsChanged;
        return;
    }
}

void setMaterial(Step& s) {
    const ScriptCommand& command = s.command;
    auto found = std::find_if(s.scene.materials.begin(), s.scene.materials.end(),
                              [&](const Material& m) { return m.name == command.target; });
    if (found == s.scene.materials.end()) return s.fail("the scene has no material \"" + command.target + "\"");
    Material& material = *found;
    // The script's names of Material's vector and number fields (the parser checked the values).
    static const std::pair<std::string_view, glm::vec3 Material::*> kVectorFields[] = {
        {"color", &Material::color}, {"emission", &Material::radiance}};
    static const std::pair<std::string_view, float Material::*> kNumberFields[] = {
        {"ior", &Material::ior},           {"roughness", &Material::roughness}, {"metallic", &Material::metallic},
        {"transmission", &Material::transmission}, {"alpha", &Material::alpha}, {"normal-scale", &Material::normalScale}};
    auto named = [&](const auto& fields) {
        return std::find_if(std::begin(fields), std::end(fields), [&](const auto& field) { return field.first == command.field; });
    };
    // A medium's fields: the medium's own, or those of the medium a refracting material holds.
    static const std::pair<std::string_view, glm::vec3 Material::*> kMediumVectorFields[] = {
        {"sigma-a", &Material::sigmaA}, {"sigma-s", &Material::sigmaS}};
    const Material before = material;
    if (command.field == "type")
        material = retypedMaterial(material, findMaterialSchema(s.word)->type);
    else if (command.field == "interior") {
        if (!materialInputTakers::refracting(materialSchema(material.type)))
            return s.fail("material \"" + command.target + "\" is " + materialSchema(material.type).name +
                          ", which does not refract: only specular_transmission, glass and principled hold a medium");
        material = withInterior(material, s.command.isWord(0, "on"));
    }
    else if (auto medium = named(kMediumVectorFields); medium != std::end(kMediumVectorFields) || command.field == "g") {
        if (!material.boundsMedium())
            return s.fail("material \"" + command.target + "\" holds no medium (a medium's type, or interior on, first)");
        if (command.field == "g") material.g = command.number(0);
        else material.*(medium->second) = command.vec3(0);
    } else if (auto vector = named(kVectorFields); vector != std::end(kVectorFields))
        material.*(vector->second) = command.vec3(0);
    else if (auto number = named(kNumberFields); number != std::end(kNumberFields))
        material.*(number->second) = command.number(0);
    else
        return setMaterialTextureField(s, material);
    // As the loader refuses it: a medium in a shape that does not enclose it. The material stays.
    if (material.boundsMedium() != before.boundsMedium())
        if (std::string problem = mediumBoundaryProblem(s.scene); !problem.empty()) {
            material = before;
            return s.fail(problem + "; the material is left as it was");
        }
    s.model.pendingChanges |= ViewerModel::kMaterialsChanged;
}

void setLight(Step& s) {
    const ScriptCommand& command = s.command;
    auto found = std::find_if(s.scene.lights.begin(), s.scene.lights.end(),
                              [&](const Light& l) { return l.name == command.target; });
    if (found == s.scene.lights.end()) return s.fail("the scene has no light \"" + command.target + "\"");
    Light& light = *found;
    if (command.field == "intensity")
        light.intensity = command.vec3(0);
    else if (command.field == "position")
        light.position = command.vec3(0);
    else if (command.field == "direction")
        light.direction = unitDirection(command.vec3(0));
    else if (command.field == "inner-angle" || command.field == "outer-angle") {
        // The file format's rule between the two (SceneRanges.h), refused here rather than at Save.
        bool inner = command.field == "inner-angle";
        float innerDeg = inner ? command.number(0) : light.innerAngleDeg;
        float outerDeg = inner ? light.outerAngleDeg : command.number(0);
        if (!ranges::coneAnglesOrdered(innerDeg, outerDeg)) {
            auto text = [](float degrees) {
                char buffer[32];
                std::snprintf(buffer, sizeof buffer, "%g", double(degrees));
                return std::string(buffer);
            };
            return s.fail(command.target + (inner ? ".inner-angle " + text(innerDeg) +
                                                        " must not exceed the outer angle (" + text(outerDeg) + ")"
                                                  : ".outer-angle " + text(outerDeg) +
                                                        " must not be less than the inner angle (" + text(innerDeg) + ")"));
        }
        light.innerAngleDeg = innerDeg;
        light.outerAngleDeg = outerDeg;
    }
    sceneEdited(s);
}

// ---- camera

// A move that leaves the camera unusable is refused here, at its line: "camera-zoom 1e38" made a
// NaN camera and the next wait-spp timed out after 120 s.
void moveCamera(Step& s, const CameraDesc& moved) {
    if (const std::string problem = cameraProblem(moved); !problem.empty())
        return s.fail("the camera would be unusable (" + problem + "); it is left as it was");
    s.scene.camera = moved;
    s.model.pendingChanges |= ViewerModel::kCameraChanged;
}

CameraDesc withFov(CameraDesc camera, float vfovDeg) {
    camera.vfovDeg = vfovDeg;
    return camera;
}

CameraDesc withAperture(CameraDesc camera, float radius) {
    camera.apertureRadius = radius;
    return camera;
}

CameraDesc withFocus(CameraDesc camera, float distance) {
    camera.focusDistance = distance;
    return camera;
}

// What Ctrl+click does, at a place given as fractions of the image; waits for the image to exist.
void focusAt(Step& s) {
    if (s.session.renderSize().x <= 0 || s.session.renderSize().y <= 0) {
        s.again = true;
        return;
    }
    if (!s.session.focusAt(glm::vec2(s.command.number(0), s.command.number(1))))
        s.fail("nothing there to focus on (the ray leaves the scene); the focus is left as it was");
}

// What the Pixel panel's "open" does: the window opens the Materials panel at that material's
// node, scrolled to the top of the sidebar (a fixed place for window tests and pictures).
void openMaterial(Step& s) {
    auto found = std::find_if(s.scene.materials.begin(), s.scene.materials.end(),
                              [&](const Material& m) { return m.name == s.word; });
    if (found == s.scene.materials.end()) return s.fail("the scene has no material \"" + s.word + "\"");
    s.panels.materialToOpen = static_cast<int>(found - s.scene.materials.begin());
}

// ---- the pixel inspector

// What Alt+click does; waits for the first sample, so that the render has its size.
void pinPixel(Step& s) {
    if (s.firstRun()) s.wait().deadline = Clock::now() + kWaitTimeout;
    s.session.update();
    if (s.session.stats(ViewerSession::Side::Left).samples == 0) {
        if (!s.session.accumulating()) s.fail("paused before the first sample: no image to pin a pixel of");
        else if (Clock::now() > s.wait().deadline) s.fail("no complete sample in time");
        s.again = !s.failed();
        return;
    }
    glm::ivec2 pixel(s.command.integer(0), s.command.integer(1));
    glm::ivec2 size = s.session.renderSize();
    if (pixel.x >= size.x || pixel.y >= size.y) {
        s.fail("pixel " + std::to_string(pixel.x) + " " + std::to_string(pixel.y) + " is outside the " +
               std::to_string(size.x) + "x" + std::to_string(size.y) + " image (x 0.." + std::to_string(size.x - 1) +
               ", y 0.." + std::to_string(size.y - 1) + " from the top-left)");
        return;
    }
    s.session.pinPixel(pixel);
    s.panels.panelsToOpen.push_back("pixel");
}

void savePixel(Step& s) {
    s.session.update();
    std::optional<PixelInspection> inspection = s.session.inspectPinnedPixel();
    if (!inspection) {
        s.fail(s.model.pinnedPixel ? "the pinned pixel is outside the render" : "no pixel is pinned (pin-pixel X Y first)");
        return;
    }
    savePixelInspection(*inspection, s.model.scene, s.word);
    std::printf("ptview: wrote %s\n", s.word.c_str());
}

void popOut(Step& s) {
    for (const DetachableSectionInfo& section : detachableSections())
        if (s.command.isWord(0, section.name)) s.panels.detached.setOut(section.section, s.command.isWord(1, "on"));
}

void resetCamera(Step& s) {
    s.session.resetCamera();
    s.model.pendingChanges |= ViewerModel::kCameraChanged;
}

// ---- waiting

void waitFrames(Step& s) {
    if (s.firstRun()) s.wait().untilFrame = s.framesDisplayed() + s.command.integer(0);
    s.again = s.framesDisplayed() < s.wait().untilFrame;
}

void waitSpp(Step& s) {
    if (s.firstRun()) s.wait().deadline = Clock::now() + kWaitTimeout;
    s.session.update(); // what was asked before this line applies first
    int target = s.command.integer(0);
    bool reached = s.session.stats(ViewerSession::Side::Left).samples >= target &&
                   (!s.session.comparing() || s.session.stats(ViewerSession::Side::Right).samples >= target);
    if (reached) return;
    if (!s.session.accumulating()) s.fail("paused or stopped at its target before " + s.word + " spp");
    else if (Clock::now() > s.wait().deadline) s.fail(s.word + " spp not reached in time");
    s.again = !s.failed();
}

// Until the main view shows a denoised image: with the denoiser on, the raw image is shown until
// the first filtering of the render ends, a few frames after its first sample.
void waitDenoised(Step& s) {
    if (s.firstRun()) s.wait().deadline = Clock::now() + kWaitTimeout;
    s.session.update();
    if (!s.session.showsDenoised(ViewerSession::Side::Left)) return s.fail("the denoiser is off: nothing to wait for");
    if (s.session.tracer(ViewerSession::Side::Left).hasDenoised()) return;
    if (Clock::now() > s.wait().deadline) s.fail("no denoised image in time");
    s.again = !s.failed();
}

void waitSeconds(Step& s) {
    using Seconds = std::chrono::duration<double>;
    if (s.firstRun())
        s.wait().deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(Seconds(s.command.number(0)));
    s.again = Clock::now() < s.wait().deadline;
}

void waitReload(Step& s) {
    if (s.firstRun()) s.wait().deadline = Clock::now() + kReloadTimeout, s.wait().reloadCount = s.session.reloadCount();
    if (s.session.reloadCount() > s.wait().reloadCount) return;
    if (Clock::now() > s.wait().deadline) s.fail("no reload within 10 s");
    s.again = !s.failed();
}

// ---- output

// Right after an edit the accumulation has started over: wait for its first complete sample, as
// `wait-spp 1` would, rather than fail with "nothing rendered yet".
void screenshot(Step& s) {
    if (s.firstRun()) s.wait().deadline = Clock::now() + kWaitTimeout;
    s.session.update();
    if (s.session.stats(ViewerSession::Side::Left).samples == 0) {
        if (!s.session.accumulating()) s.fail("paused before the first sample: nothing to save");
        else if (Clock::now() > s.wait().deadline) s.fail("no complete sample in time");
        s.again = !s.failed();
        return;
    }
    s.session.writeImage(ViewerSession::Side::Left, s.word);
}

// Written by the window after this frame, where the script's line is no longer known.
void screenshotWindow(Step& s) {
    if (std::optional<std::string> problem = outputPathProblem(s.word, {".png"})) s.fail(*problem);
    else s.takeWindowScreenshot(s.word);
}

void saveScreenshotsNow(Step& s) {
    saveScreenshots(s.session, s.panels);
    if (s.panels.screenshotFailed) s.fail(s.panels.screenshotMessage);
    else std::printf("%s\n", s.panels.screenshotMessage.c_str());
}

// ---- the paths behind the pinned pixel

// What the Pixel panel's "Trace paths" does, on the render the view has now.
void tracePaths(Step& s) {
    s.session.update();
    if (!s.model.pinnedPixel) {
        s.fail("no pixel is pinned (pin-pixel X Y first)");
        return;
    }
    const ViewerSession::TracedPaths& traced = s.session.tracePaths(*s.model.pinnedPixel, s.model.pathCount);
    s.panels.selectedPath = PathPick{0, -1};
    std::printf("ptview: traced %zu paths of pixel %d %d\n", traced.paths.size(), traced.pixel.x, traced.pixel.y);
}

void savePaths(Step& s) {
    const std::optional<ViewerSession::TracedPaths>& traced = s.session.tracedPaths();
    if (!traced) {
        s.fail("no paths traced (trace-paths first)");
        return;
    }
    PathsReport report;
    report.scenePath = s.model.scene.path.string();
    report.scene = &s.model.scene;
    report.settings = traced->settings;
    report.imageSize = traced->imageSize;
    report.pixel = traced->pixel;
    report.paths = &traced->paths;
    writeFileAtomically(s.word, pathsToJson(report));
    std::printf("ptview: wrote %s\n", s.word.c_str());
}

std::filesystem::path pathOrNone(const Step& s) {
    return s.command.isWord(0, "none") ? std::filesystem::path() : std::filesystem::path(s.word);
}

// Every verb of the script table and what it does: what the matching UI control does.
const std::vector<std::pair<const char*, Handler>>& handlers() {
    static const std::vector<std::pair<const char*, Handler>> table = {
        // ---- render settings
        {"integrator", [](Step& s) { s.model.settings.integrator = integratorNamed(s.word); }},
        {"sampler", [](Step& s) { s.model.settings.sampler = *parseSamplerMode(s.word); }},
        {"depth", [](Step& s) { s.model.settings.maxDepth = s.command.integer(0); }},
        {"clamp",
         [](Step& s) {
             s.model.settings.radianceClamp = s.command.isWord(0, "off") ? std::nullopt : std::optional<float>(s.command.number(0));
         }},
        {"light-paths",
         [](Step& s) { s.model.settings.lightPaths = lightPathsNames().parse(s.word).value_or(LightPaths::All); }},
        {"light-path-bounces", [](Step& s) { s.model.settings.lightPathBounces = s.command.integer(0); }},
        {"seed", [](Step& s) { s.model.settings.seed = s.command.unsignedInteger(0); }},
        {"exposure", [](Step& s) { s.model.display.exposureStops = s.command.number(0); }},
        {"tone-mapper", [](Step& s) { s.model.display.toneMapper = toneMapperNamed(s.word); }},
        {"display-transfer", [](Step& s) { s.model.display.transfer = displayTransferNamed(s.word); }},
        {"ocio-config", [](Step& s) {
             if (!s.session.setOcioView({pathOrNone(s).string(), "", ""})) s.fail(s.model.ocioError);
         }},
        {"ocio-display", [](Step& s) {
             if (!s.session.setOcioView({s.model.ocio.config, s.word, ""})) s.fail(s.model.ocioError);
         }},
        {"ocio-view", [](Step& s) {
             if (!s.session.setOcioView({s.model.ocio.config, s.model.ocio.display, s.word})) s.fail(s.model.ocioError);
         }},
        {"resolution-scale", [](Step& s) { s.model.resolutionScale = s.command.number(0); }},
        {"samples-per-frame",
         [](Step& s) { s.model.maxSamplesPerFrame = s.command.isWord(0, "auto") ? 0 : s.command.integer(0); }},
        {"pause", [](Step& s) { s.model.paused = true; }},
        {"resume", [](Step& s) { s.model.paused = false; }},
        {"target-spp", [](Step& s) { s.model.targetSamples = s.command.integer(0); }},
        {"target-error", [](Step& s) {
             s.model.targetErrorOn = !s.command.isWord(0, "off");
             if (s.model.targetErrorOn) s.model.targetError = static_cast<float>(s.command.number(0));
         }},
        // ---- the denoiser
        {"denoise", [](Step& s) { s.model.denoise.enabled = s.command.isWord(0, "on"); }},
        {"denoise-strength", [](Step& s) { s.model.denoise.strength = s.command.number(0); }},
        {"denoise-iterations", [](Step& s) { s.model.denoise.iterations = s.command.integer(0); }},
        {"denoise-algorithm", [](Step& s) { s.model.denoise.algorithm = *denoiseAlgorithmNames().parse(s.word); }},
        // ---- scene edits
        {"set-material", setMaterial},
        {"set-light", setLight},
        {"environment", [](Step& s) { s.session.setEnvironmentMap(pathOrNone(s)); }},
        {"environment-intensity", [](Step& s) { s.scene.environmentIntensity = s.command.number(0); sceneEdited(s); }},
        {"environment-rotation", [](Step& s) { s.scene.environmentRotationDeg = s.command.number(0); sceneEdited(s); }},
        {"environment-color", [](Step& s) { s.scene.environment = s.command.vec3(0); sceneEdited(s); }},
        // ---- camera
        {"camera-orbit", [](Step& s) { moveCamera(s, orbitCamera(s.scene.camera, s.command.number(0), s.command.number(1))); }},
        {"camera-pan", [](Step& s) { moveCamera(s, panCamera(s.scene.camera, s.command.number(0), s.command.number(1))); }},
        {"camera-zoom", [](Step& s) { moveCamera(s, zoomCamera(s.scene.camera, s.command.number(0))); }},
        {"camera-fov", [](Step& s) { moveCamera(s, withFov(s.scene.camera, s.command.number(0))); }},
        {"camera-aperture", [](Step& s) { moveCamera(s, withAperture(s.scene.camera, s.command.number(0))); }},
        {"camera-focus", [](Step& s) { moveCamera(s, withFocus(s.scene.camera, s.command.number(0))); }},
        {"camera-focus-at", focusAt},
        {"camera-reset", resetCamera},
        // ---- undo and redo
        {"undo", [](Step& s) {
             if (!undoEdit(s.session, s.panels)) s.fail(s.panels.imageNotice);
         }},
        {"redo", [](Step& s) {
             if (!redoEdit(s.session, s.panels)) s.fail(s.panels.imageNotice);
         }},
        // ---- files
        {"load-scene", [](Step& s) {
             std::vector<std::string> edits = s.session.unsavedEdits();
             // A bad file shows in the UI (and status), as a click would, and keeps the edits.
             if (s.session.openScene(s.word)) s.noteDiscardedEdits(edits);
         }},
        {"reload", [](Step& s) { s.session.reloadScene(); }},
        {"wait-reload", waitReload},
        {"save-scene", [](Step& s) { s.session.saveSceneAs(s.word); }},
        {"copy-file", [](Step& s) {
             std::filesystem::copy_file(s.command.words[0], s.command.words[1], std::filesystem::copy_options::overwrite_existing);
         }},
        // ---- compare mode
        {"compare", [](Step& s) { s.model.compare.enabled = s.command.isWord(0, "on"); }},
        {"compare-sides", [](Step& s) {
             s.model.compare.sides = s.command.isWord(0, "raw-denoised") ? CompareSides::RawAndDenoised
                                     : s.command.isWord(0, "image-view") ? CompareSides::ImageAndView
                                                                         : CompareSides::TwoRenders;
         }},
        {"compare-denoise", [](Step& s) { s.model.compare.rightDenoised = s.command.isWord(0, "on"); }},
        {"compare-integrator", [](Step& s) { s.model.compare.right.integrator = integratorNamed(s.word); }},
        {"compare-sampler", [](Step& s) { s.model.compare.right.sampler = *parseSamplerMode(s.word); }},
        {"compare-depth", [](Step& s) { s.model.compare.right.maxDepth = s.command.integer(0); }},
        {"divider", [](Step& s) { s.model.compare.dividerFraction = s.command.number(0); }},
        {"view", [](Step& s) { s.model.display.view = displayViewNames().parse(s.word).value_or(DisplayView::Image); }},
        {"error-range", [](Step& s) {
             if (!(s.command.number(0) < s.command.number(1))) return s.fail("LO must be below HI");
             s.model.display.mapRange.errorLog10Min = std::clamp(std::log10(s.command.number(0)), kErrorLog10Lowest, kErrorLog10Highest);
             s.model.display.mapRange.errorLog10Max = std::clamp(std::log10(s.command.number(1)), kErrorLog10Lowest, kErrorLog10Highest);
             if (s.model.display.mapRange.errorLog10Max <= s.model.display.mapRange.errorLog10Min)
                 s.model.display.mapRange.errorLog10Max = s.model.display.mapRange.errorLog10Min + 1.0f; // both beyond one end
         }},
        {"difference-range", [](Step& s) {
             s.model.display.mapRange.differenceRange = std::max(s.command.number(0), kDifferenceRangeMin);
         }},
        // A bad file shows in the UI (and status), as the panel's Load would, and keeps the image before.
        {"load-compare-image", [](Step& s) { s.session.setCompareImage(pathOrNone(s)); }},
        {"zoom", [](Step& s) {
             s.session.update(); // the render's size as it is now
             if (s.command.isWord(0, "fit")) s.session.fitImage();
             else s.session.zoomImageTo(s.command.number(0));
         }},
        {"pan", [](Step& s) {
             s.session.update();
             s.session.panImage(glm::vec2(s.command.number(0), -s.command.number(1))); // DY counts down, GL up
         }},
        // ---- waiting and output
        {"frames", waitFrames},
        {"wait-spp", waitSpp},
        {"wait-denoised", waitDenoised},
        {"wait-seconds", waitSeconds},
        {"screenshot", screenshot},
        {"screenshot-window", screenshotWindow},
        {"save-screenshots", saveScreenshotsNow},
        {"path-count", [](Step& s) { s.model.pathCount = s.command.integer(0); }},
        {"trace-paths", tracePaths},
        {"save-paths", savePaths},
        {"reference", [](Step& s) {
             if (!s.session.setReference(pathOrNone(s))) s.fail(s.session.model().sceneError);
         }},
        {"open-panel", [](Step& s) { s.panels.panelsToOpen.push_back(s.word); }},
        {"open-material", openMaterial},
        {"pop-out", popOut},
        {"ui-scale", [](Step& s) {
             std::string clamped;
             s.panels.preferences.uiScale = clampedUiScale(s.command.number(0), &clamped);
             if (!clamped.empty()) s.note(clamped);
         }},
        {"high-contrast", [](Step& s) { s.panels.preferences.highContrast = s.command.isWord(0, "on"); }},
        {"pin-pixel", pinPixel},
        {"unpin-pixel", [](Step& s) { s.model.pinnedPixel.reset(); }},
        {"save-pixel", savePixel},
        {"status", [](Step& s) {
             s.session.update();
             printStatus(s.session, s.panels);
         }},
        {"quit", [](Step& s) {
             s.noteDiscardedEdits(s.session.unsavedEdits());
             s.quit();
         }},
    };
    return table;
}

Handler findHandler(const std::string& verb) {
    for (const auto& [name, handler] : handlers())
        if (verb == name) return handler;
    return nullptr;
}

} // namespace

std::vector<std::string> ScriptRunner::handledVerbs() {
    std::vector<std::string> verbs;
    for (const auto& entry : handlers()) verbs.emplace_back(entry.first);
    return verbs;
}

bool ScriptRunner::run(const ScriptCommand& command, ViewerSession& session, PanelState& panels) {
    Step step(*this, command, session, panels);
    try {
        // The parser accepts only the table's verbs, and each has a handler (ScriptRunnerTest).
        if (Handler handler = findHandler(command.verb)) handler(step);
        else fail(command, "not implemented by this viewer");
    } catch (const std::exception& e) {
        fail(command, e.what());
        return true;
    }
    return !step.again;
}

} // namespace ptview
