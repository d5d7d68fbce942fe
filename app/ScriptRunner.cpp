#include "ScriptRunner.h"

#include "CameraController.h"
#include "MaterialSchema.h"
#include "MaterialsPanel.h"
#include "OutputPath.h"
#include "SceneRanges.h"

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace ptview {
namespace {

// Long enough for a slow software rasterizer to reach a few hundred samples of a small image.
constexpr std::chrono::seconds kWaitTimeout{120};
constexpr std::chrono::seconds kReloadTimeout{10};

// The parser checked the names: the fallbacks are unreachable.
Integrator integratorNamed(const std::string& name) { return integratorNames().parse(name).value_or(Integrator::Naive); }
ToneMapper toneMapperNamed(const std::string& name) { return toneMapperNames().parse(name).value_or(ToneMapper::Reinhard); }

// Quoted for the status line: one line, quotes and backslashes escaped.
std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += c == '\n' ? ' ' : c;
    }
    return out + "\"";
}

std::string vectorText(const glm::vec3& v) {
    char text[96];
    std::snprintf(text, sizeof(text), "%.6g,%.6g,%.6g", v.x, v.y, v.z);
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
                       " target-spp=" + std::to_string(model.targetSamples) +
                       " backend=" + backendName(session.tracer(ViewerSession::Side::Left).backend()) +
                       " reloads=" + std::to_string(session.reloadCount()) + " eye=" + vectorText(model.scene.camera.eye) +
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
    std::vector<std::string> edits = session.unsavedEdits();
    std::optional<UnsavedEditsPrompt::Action> asking = panels.unsavedEdits.pending();
    line += " edits=" + (edits.empty() ? std::string("none") : joined(edits, ",")) +
            " prompt=" + (asking ? actionName(*asking) : "none") + " save-target=" + quoted(session.saveTarget());
    line += " scene=" + quoted(model.scene.path.string()) + " scene-error=" + quoted(model.sceneError) +
            " shader-error=" + quoted(model.shaderError);
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
}

} // namespace

// A script answers no questions: what it throws away it says on stderr.
void ScriptRunner::noteDiscardedEdits(const ScriptCommand& command, const std::vector<std::string>& edits) const {
    if (edits.empty()) return;
    std::cerr << "ptview: " << script_.path.string() << ":" << command.line << ": " << command.verb
              << ": discarded unsaved edits (" << joined(edits, ", ") << ")\n";
}

void ScriptRunner::fail(const ScriptCommand& command, const std::string& reason) {
    std::cerr << "ptview: " << script_.path.string() << ":" << command.line << ": " << command.verb << ": " << reason
              << "\n";
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
        waiting_ = false;
        ++next_;
    }
}

bool ScriptRunner::run(const ScriptCommand& command, ViewerSession& session, PanelState& panels) {
    ViewerModel& model = session.model();
    Scene& scene = model.scene;
    const std::string& verb = command.verb;
    const std::string& word = command.words.empty() ? std::string() : command.words[0];
    try {
        // ---- render settings
        if (verb == "integrator") {
            model.settings.integrator = integratorNamed(word);
        } else if (verb == "sampler") {
            model.settings.sampler = *parseSamplerMode(word);
        } else if (verb == "depth") {
            model.settings.maxDepth = command.integer(0);
        } else if (verb == "seed") {
            model.settings.seed = command.unsignedInteger(0);
        } else if (verb == "exposure") {
            model.display.exposureStops = command.number(0);
        } else if (verb == "tone-mapper") {
            model.display.toneMapper = toneMapperNamed(word);
        } else if (verb == "resolution-scale") {
            model.resolutionScale = command.number(0);
        } else if (verb == "samples-per-frame") {
            model.maxSamplesPerFrame = command.isWord(0, "auto") ? 0 : command.integer(0);
        } else if (verb == "pause" || verb == "resume") {
            model.paused = verb == "pause";
        } else if (verb == "target-spp") {
            model.targetSamples = command.integer(0);
        // ---- scene edits
        } else if (verb == "set-material") {
            auto found = std::find_if(scene.materials.begin(), scene.materials.end(),
                                      [&](const Material& m) { return m.name == command.target; });
            if (found == scene.materials.end()) {
                fail(command, "the scene has no material \"" + command.target + "\"");
                return true;
            }
            Material& material = *found;
            if (command.field == "type")
                material = retypedMaterial(material, findMaterialSchema(word)->type);
            else if (command.field == "color")
                material.color = command.vec3(0);
            else if (command.field == "emission")
                material.radiance = command.vec3(0);
            else if (command.field == "ior")
                material.ior = command.number(0);
            else if (command.field == "roughness")
                material.roughness = command.number(0);
            model.pendingChanges |= ViewerModel::kMaterialsChanged;
        } else if (verb == "set-light") {
            auto found = std::find_if(scene.lights.begin(), scene.lights.end(),
                                      [&](const Light& l) { return l.name == command.target; });
            if (found == scene.lights.end()) {
                fail(command, "the scene has no light \"" + command.target + "\"");
                return true;
            }
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
                    fail(command, command.target + (inner ? ".inner-angle " + text(innerDeg) +
                                                                " must not exceed the outer angle (" + text(outerDeg) + ")"
                                                          : ".outer-angle " + text(outerDeg) +
                                                                " must not be less than the inner angle (" + text(innerDeg) + ")"));
                    return true;
                }
                light.innerAngleDeg = innerDeg;
                light.outerAngleDeg = outerDeg;
            }
            model.pendingChanges |= ViewerModel::kSceneChanged;
        } else if (verb == "environment") {
            session.setEnvironmentMap(command.isWord(0, "none") ? std::filesystem::path() : std::filesystem::path(word));
        } else if (verb == "environment-intensity") {
            scene.environmentIntensity = command.number(0);
            model.pendingChanges |= ViewerModel::kSceneChanged;
        } else if (verb == "environment-rotation") {
            scene.environmentRotationDeg = command.number(0);
            model.pendingChanges |= ViewerModel::kSceneChanged;
        } else if (verb == "environment-color") {
            scene.environment = command.vec3(0);
            model.pendingChanges |= ViewerModel::kSceneChanged;
        // ---- camera
        } else if (verb.rfind("camera-", 0) == 0) {
            CameraDesc camera = scene.camera;
            if (verb == "camera-orbit") camera = orbitCamera(camera, command.number(0), command.number(1));
            if (verb == "camera-pan") camera = panCamera(camera, command.number(0), command.number(1));
            if (verb == "camera-zoom") camera = zoomCamera(camera, command.number(0));
            if (verb == "camera-fov") camera.vfovDeg = command.number(0);
            // A move that leaves the camera unusable is refused here, at its line: "camera-zoom 1e38"
            // made a NaN camera and the next wait-spp timed out after 120 s.
            if (const std::string problem = cameraProblem(camera); !problem.empty()) {
                fail(command, "the camera would be unusable (" + problem + "); it is left as it was");
                return true;
            }
            scene.camera = camera;
            if (verb == "camera-reset") session.resetCamera();
            model.pendingChanges |= ViewerModel::kCameraChanged;
        // ---- files
        } else if (verb == "load-scene") {
            std::vector<std::string> edits = session.unsavedEdits();
            // A bad file shows in the UI (and status), as a click would, and keeps the edits.
            if (session.openScene(word)) noteDiscardedEdits(command, edits);
        } else if (verb == "reload") {
            session.reloadScene();
        } else if (verb == "save-scene") {
            session.saveSceneAs(word);
        } else if (verb == "copy-file") {
            std::filesystem::copy_file(command.words[0], command.words[1],
                                       std::filesystem::copy_options::overwrite_existing);
        // ---- compare mode
        } else if (verb == "compare") {
            model.compare.enabled = command.isWord(0, "on");
        } else if (verb == "compare-integrator") {
            model.compare.right.integrator = integratorNamed(word);
        } else if (verb == "compare-sampler") {
            model.compare.right.sampler = *parseSamplerMode(word);
        } else if (verb == "compare-depth") {
            model.compare.right.maxDepth = command.integer(0);
        } else if (verb == "divider") {
            model.compare.dividerFraction = command.number(0);
        // ---- waiting
        } else if (verb == "frames") {
            if (!waiting_) waiting_ = true, waitUntilFrame_ = framesDisplayed_ + command.integer(0);
            return framesDisplayed_ >= waitUntilFrame_;
        } else if (verb == "wait-spp") {
            if (!waiting_) waiting_ = true, waitDeadline_ = Clock::now() + kWaitTimeout;
            session.update(); // what was asked before this line applies first
            int target = command.integer(0);
            bool reached = session.stats(ViewerSession::Side::Left).samples >= target &&
                           (!session.comparing() || session.stats(ViewerSession::Side::Right).samples >= target);
            if (reached) return true;
            if (!session.accumulating()) fail(command, "paused or stopped at its target before " + word + " spp");
            else if (Clock::now() > waitDeadline_) fail(command, word + " spp not reached in time");
            return quit_;
        } else if (verb == "wait-seconds") {
            using Seconds = std::chrono::duration<double>;
            if (!waiting_) waiting_ = true, waitDeadline_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(Seconds(command.number(0)));
            return Clock::now() >= waitDeadline_;
        } else if (verb == "wait-reload") {
            if (!waiting_) waiting_ = true, waitDeadline_ = Clock::now() + kReloadTimeout, reloadCountAtWait_ = session.reloadCount();
            if (session.reloadCount() > reloadCountAtWait_) return true;
            if (Clock::now() > waitDeadline_) fail(command, "no reload within 10 s");
            return quit_;
        // ---- output
        } else if (verb == "screenshot") {
            // Right after an edit the accumulation has started over: wait for its first complete
            // sample, as `wait-spp 1` would, rather than fail with "nothing rendered yet".
            if (!waiting_) waiting_ = true, waitDeadline_ = Clock::now() + kWaitTimeout;
            session.update();
            if (session.stats(ViewerSession::Side::Left).samples == 0) {
                if (!session.accumulating()) fail(command, "paused before the first sample: nothing to save");
                else if (Clock::now() > waitDeadline_) fail(command, "no complete sample in time");
                return quit_;
            }
            session.writeImage(ViewerSession::Side::Left, word);
        } else if (verb == "screenshot-window") {
            // Written by the window after this frame, where the script's line is no longer known.
            if (std::optional<std::string> problem = outputPathProblem(word, {".png"})) fail(command, *problem);
            else windowScreenshot_ = std::filesystem::path(word);
        } else if (verb == "save-screenshots") {
            saveScreenshots(session, panels);
            if (panels.screenshotFailed) fail(command, panels.screenshotMessage);
            else std::printf("%s\n", panels.screenshotMessage.c_str());
        } else if (verb == "reference") {
            if (!session.setReference(command.isWord(0, "none") ? std::filesystem::path() : std::filesystem::path(word)))
                fail(command, session.model().sceneError);
        } else if (verb == "open-panel") {
            panels.panelsToOpen.push_back(word);
        } else if (verb == "status") {
            session.update();
            printStatus(session, panels);
        } else if (verb == "quit") {
            noteDiscardedEdits(command, session.unsavedEdits());
            quit_ = true;
        } else {
            fail(command, "not implemented by this viewer");
        }
    } catch (const std::exception& e) {
        fail(command, e.what());
    }
    return true;
}

} // namespace ptview
