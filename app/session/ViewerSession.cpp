#include <ptview/session/ViewerSession.h>

#include <ptview/io/ExrIO.h>
#include <ptview/gl/HeadlessContext.h>
#include <ptview/io/ImageIO.h>
#include <ptview/io/Image.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/model/SceneMerge.h>
#include <ptview/scene/SceneWriter.h>
#include <ptview/provenance/Provenance.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <stdexcept>

namespace ptview {
namespace {

using Clock = std::chrono::steady_clock;

constexpr double kErrorEstimateIntervalSeconds = 1.0;
constexpr double kResizeSettleSeconds = 0.3;
constexpr size_t kErrorHistoryLength = 512;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

std::shared_ptr<const EnvironmentMap> shareMap(std::optional<EnvironmentMap>& map) {
    return map ? std::make_shared<const EnvironmentMap>(std::move(*map)) : nullptr;
}

std::vector<std::filesystem::path> shaderFiles(const std::filesystem::path& directory) {
    std::vector<std::filesystem::path> files;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
        std::string extension = entry.path().extension().string();
        if (extension == ".glsl" || extension == ".frag" || extension == ".vert") files.push_back(entry.path());
    }
    return files;
}

// "cornell-20261123-071530": sorts by time and says what it shows.
std::string screenshotStem(const Scene& scene) {
    std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char time[32];
    std::strftime(time, sizeof(time), "%Y%m%d-%H%M%S", &local);
    std::string name = scene.path.empty() ? "scene" : scene.path.stem().string();
    return name + "-" + time;
}

} // namespace

ViewerSession::ViewerSession(SceneInput input, const RenderSettings& settings, const DisplaySettings& display,
                             std::filesystem::path shaderDir, PathTracerOptions program)
    : shaderDir_(std::move(shaderDir)), programOptions_(program) {
    model_.environmentMap = shareMap(input.environmentMap);
    model_.scene = std::move(input.scene);
    allowedDirectories_ = std::move(input.allowedDirectories);
    if (!input.carriedBy.empty()) {
        // The scene file an image names is the sender's word, not a file of the user's: it is
        // neither written by Save nor watched for reload (docs/robustness.md).
        const std::filesystem::path named = model_.scene.path;
        model_.scene.path.clear();
        carriedSceneUnsaved_ = !input.carriedSceneIsInItsFile;
        model_.notice = "opened the scene carried by " + input.carriedBy.string() +
                        (carriedSceneUnsaved_ ? "; it differs from " + named.string() + " (or that file cannot be read from the image's folder)"
                                              : "; it is the scene of " + named.string()) +
                        "; it has no file of its own: type one in Materials > Save scene as to save it";
    }
    model_.fileScene = model_.scene;
    model_.settings = settings;
    model_.display = display;
    model_.compare.right = settings;
    left_.tracer =
        std::make_unique<PathTracer>(makePathTracer(model_.scene, model_.environmentMap.get(), programOptions_, settings, shaderDir_));
    left_.tracer->setPreviewEnabled(true);
    if (program.backend) {
        model_.backend = *program.backend;
    } else {
        BackendChoice choice = left_.tracer->chooseBackend();
        model_.backend = choice.backend;
        model_.backendChoice = choice.describe();
    }
    saveTarget_ = model_.fileScene.path.string();
    history_.reset(SceneEdits::of(model_.scene, model_.environmentMap));
    watchFiles();
}

ViewerSession::~ViewerSession() = default;

// ---- actions ---------------------------------------------------------------------------------

void ViewerSession::applyScene(Scene scene, std::shared_ptr<const EnvironmentMap> map) {
    model_.scene = std::move(scene);
    model_.environmentMap = std::move(map);
    model_.pendingChanges |= ViewerModel::kSceneChanged | ViewerModel::kCameraChanged;
    model_.sceneError.clear();
    watchFiles();
}

bool ViewerSession::openScene(const std::filesystem::path& path) {
    ++reloadCount_;
    try {
        Scene scene = loadScene(path, ReadScope::anywhere(allowedDirectories_));
        std::optional<EnvironmentMap> loaded;
        if (!scene.environmentMap.empty()) loaded = loadEnvironmentMap(scene.environmentMap);
        std::shared_ptr<const EnvironmentMap> map = shareMap(loaded);
        // The open scene's file again (Reload, its edits discarded): the history goes on, rebased
        // onto the file as a reload would, and the discard is a step that undo takes back.
        std::error_code error;
        const bool sameFile = !model_.fileScene.path.empty() && std::filesystem::equivalent(path, model_.fileScene.path, error);
        if (sameFile) {
            recordEdits();
            history_.rebase(model_.fileScene, scene, SceneEdits::of(scene, map));
        }
        model_.fileScene = scene;
        carriedSceneUnsaved_ = false;
        saveTarget_ = path.string(); // Save must not write the new scene over the last one's file
        model_.notice = "opened " + path.string();
        for (const std::string& warning : scene.warnings) model_.notice += "\nwarning: " + warning;
        applyScene(std::move(scene), std::move(map));
        if (sameFile)
            history_.record(model_.scene, model_.environmentMap, false, "discarding the edits (" + path.filename().string() + " read again)");
        else
            history_.reset(SceneEdits::of(model_.scene, model_.environmentMap));
        return true;
    } catch (const std::exception& e) { // SceneError, EnvironmentMapError: both name the file
        model_.sceneError = e.what();
        return false;
    }
}

bool ViewerSession::reloadScene() {
    ++reloadCount_;
    try {
        Scene reloaded = loadScene(model_.fileScene.path, ReadScope::anywhere(allowedDirectories_));
        std::shared_ptr<const EnvironmentMap> map = model_.environmentMap;
        SceneMergeResult merged = mergeReloadedScene(model_.fileScene, model_.scene, reloaded);
        if (merged.scene.environmentMap != model_.scene.environmentMap || !map) {
            std::optional<EnvironmentMap> loaded;
            if (!merged.scene.environmentMap.empty()) loaded = loadEnvironmentMap(merged.scene.environmentMap);
            map = shareMap(loaded);
        }
        // The edits so far are steps of their own, each now on top of the new file.
        recordEdits();
        history_.rebase(model_.fileScene, reloaded, SceneEdits::of(merged.scene, map));
        model_.fileScene = std::move(reloaded);
        applyScene(std::move(merged.scene), std::move(map));
        model_.notice = "reloaded " + model_.fileScene.path.string();
        for (const std::string& item : merged.overridden) model_.notice += "; the file replaced your edit of " + item;
        return true;
    } catch (const std::exception& e) {
        model_.sceneError = e.what();
        return false;
    }
}

bool ViewerSession::setEnvironmentMap(const std::filesystem::path& path) {
    try {
        std::shared_ptr<const EnvironmentMap> map;
        if (!path.empty()) map = std::make_shared<const EnvironmentMap>(loadEnvironmentMap(path));
        model_.scene.environmentMap = path;
        model_.environmentMap = std::move(map);
        model_.pendingChanges |= ViewerModel::kSceneChanged;
        model_.sceneError.clear();
        if (!path.empty()) history_.shareEnvironmentMap(path, model_.environmentMap); // read again: its file changed
        watchFiles();
        return true;
    } catch (const std::exception& e) {
        model_.sceneError = e.what();
        return false;
    }
}

bool ViewerSession::setReference(const std::filesystem::path& path) {
    try {
        model_.reference = path.empty() ? nullptr : std::make_shared<const ImageRgbF>(readReferenceImage(path));
        model_.referencePath = path;
        left_.trueErrorHistory.clear();
        if (right_) right_->trueErrorHistory.clear();
        syncOtherImages(); // the error map's
        // Judged at once, so that a finished render (no more frames of work) gets its true error too.
        for (View* view : {&left_, right_.get()}) {
            if (!view) continue;
            view->trueError.reset();
            view->estimatedSamples = 0;
            view->lastEstimate = {};
            updateErrorEstimate(*view);
        }
        return true;
    } catch (const std::exception& e) {
        model_.sceneError = e.what();
        return false;
    }
}

bool ViewerSession::setCompareImage(const std::filesystem::path& path) {
    try {
        std::shared_ptr<const ImageRgbF> image;
        if (!path.empty()) {
            image = std::make_shared<const ImageRgbF>(readReferenceImage(path)); // finite, or a message naming the pixel
            if (renderSize_.x > 0 && (image->width != renderSize_.x || image->height != renderSize_.y))
                throw std::runtime_error(path.string() + " is " + std::to_string(image->width) + "x" +
                                         std::to_string(image->height) + " but the render is " + std::to_string(renderSize_.x) +
                                         "x" + std::to_string(renderSize_.y) +
                                         "; a comparison image must be of the render's size (kept the one before)");
        }
        model_.compareImage = std::move(image);
        model_.compareImagePath = path;
        model_.sceneError.clear();
        model_.notice = path.empty() ? "no comparison image" : "comparison image " + path.string();
        syncOtherImages();
        return true;
    } catch (const std::exception& e) {
        model_.sceneError = e.what();
        return false;
    }
}

std::shared_ptr<const ImageRgbF> ViewerSession::otherImageFor(DisplayView view) const {
    if (viewNeedsReference(view)) return model_.reference;
    if (viewNeedsOtherImage(view)) return model_.compareImage ? model_.compareImage : model_.reference;
    return nullptr;
}

std::string ViewerSession::viewProblem(Side side) const {
    DisplayView view = displaySettings(side).view;
    if (!viewNeedsReference(view) && !viewNeedsOtherImage(view)) return "";
    std::shared_ptr<const ImageRgbF> other = otherImageFor(view);
    const char* needed = viewNeedsReference(view) ? "a reference (Stats panel, or `reference FILE`)"
                                                  : "a comparison image or a reference";
    if (!other) return std::string(displayViewName(view)) + " needs " + needed + ": showing the image";
    if (other->width != renderSize_.x || other->height != renderSize_.y)
        return std::string(displayViewName(view)) + ": the other image is " + std::to_string(other->width) + "x" +
               std::to_string(other->height) + ", the render " + std::to_string(renderSize_.x) + "x" +
               std::to_string(renderSize_.y) + ": showing the image";
    return "";
}

// Each tracer gets the image its side's view compares with (uploaded only when it changes). A
// split of one render (raw | denoised, image | view) draws both sides with the left tracer, whose
// left side then shows the image, which needs none.
void ViewerSession::syncOtherImages() {
    DisplayView leftView = displaySettings(Side::Left).view;
    DisplayView rightView = displaySettings(Side::Right).view;
    bool oneRender = comparing() && !comparesTwoRenders();
    left_.tracer->setOtherImage(otherImageFor(oneRender && leftView == DisplayView::Image ? rightView : leftView));
    if (right_) right_->tracer->setOtherImage(otherImageFor(rightView));
}

std::optional<glm::ivec2> ViewerSession::pixelAtFramebuffer(glm::vec2 framebufferPos) const {
    PixelRect view = viewArea();
    if (framebufferPos.x < static_cast<float>(view.origin.x) || framebufferPos.y < static_cast<float>(view.origin.y) ||
        framebufferPos.x >= static_cast<float>(view.origin.x + view.size.x) ||
        framebufferPos.y >= static_cast<float>(view.origin.y + view.size.y))
        return std::nullopt;
    return renderPixelAt(framebufferPos, imageRect(), renderSize_);
}

PixelRect ViewerSession::imageRect() const {
    return zoomedImageRect(model_.zoom, imageArea_, displayArea(), renderSize_);
}

PixelRect ViewerSession::viewArea() const {
    return model_.zoom.fit() ? displayArea() : imageArea_;
}

void ViewerSession::zoomImageTo(float scale, std::optional<glm::vec2> aboutFramebufferPos) {
    scale = std::clamp(scale, kMinZoomScale, kMaxZoomScale);
    glm::vec2 about = aboutFramebufferPos ? *aboutFramebufferPos
                                          : glm::vec2(imageArea_.origin) + 0.5f * glm::vec2(imageArea_.size);
    model_.zoom = zoomedAbout(model_.zoom, scale, about, imageArea_, displayArea(), renderSize_);
}

void ViewerSession::zoomImageBySteps(int steps, std::optional<glm::vec2> aboutFramebufferPos) {
    zoomImageTo(steppedZoomScale(shownZoomScale(model_.zoom, displayArea(), renderSize_), steps), aboutFramebufferPos);
}

void ViewerSession::panImage(glm::vec2 framebufferDelta) {
    model_.zoom = pannedBy(model_.zoom, framebufferDelta, displayArea(), renderSize_);
}

// ---- undo and redo ---------------------------------------------------------------------------

void ViewerSession::recordEdits(bool inProgress) {
    history_.record(model_.scene, model_.environmentMap, inProgress);
}

// The scene's edits as `state` has them, and the flags of what that changes. The map is the
// state's own decoded one where it names another; read again only when no state held it.
bool ViewerSession::restoreEdits(const SceneEdits& state) {
    std::shared_ptr<const EnvironmentMap> map = model_.environmentMap;
    const bool mapChanged = state.environmentMap != model_.scene.environmentMap;
    if (mapChanged) {
        map = state.environmentMapData;
        if (!map && !state.environmentMap.empty()) {
            try {
                map = std::make_shared<const EnvironmentMap>(loadEnvironmentMap(state.environmentMap));
            } catch (const std::exception& e) { // names the file
                model_.sceneError = e.what();
                return false;
            }
        }
    }
    model_.pendingChanges |= changesBetween(SceneEdits::of(model_.scene), state);
    state.applyTo(model_.scene);
    model_.environmentMap = std::move(map);
    if (mapChanged) watchFiles();
    return true;
}

bool ViewerSession::undo() {
    recordEdits();
    const SceneEdits& last = history_.current();
    if (!sameEdits(last, model_.scene)) {
        // An edit the history refused: undoing it goes back to the last good state.
        const std::string label = describeEdit(last, SceneEdits::of(model_.scene));
        if (!restoreEdits(last)) return false;
        model_.notice = "undid " + label;
        return true;
    }
    const SceneEdits* target = history_.undoTarget();
    if (!target) {
        model_.notice = "nothing to undo";
        return false;
    }
    const std::string label = history_.undoLabel();
    if (!restoreEdits(*target)) return false;
    history_.undo();
    model_.notice = "undid " + label;
    return true;
}

bool ViewerSession::redo() {
    recordEdits();
    const SceneEdits* target = history_.redoTarget();
    if (!target) {
        model_.notice = "nothing to redo";
        return false;
    }
    const std::string label = history_.redoLabel();
    if (!restoreEdits(*target)) return false;
    history_.redo();
    model_.notice = "redid " + label;
    return true;
}

void ViewerSession::resetCamera() {
    model_.scene.camera = model_.fileScene.camera;
    model_.pendingChanges |= ViewerModel::kCameraChanged;
}

std::optional<float> ViewerSession::focusAt(glm::vec2 imageFraction) {
    update(); // the tracer looks with the camera the user sees
    PathTracer& tracer = *left_.tracer;
    glm::vec2 size(tracer.imageSize());
    glm::vec2 filmPos(imageFraction.x * size.x, (1.0f - imageFraction.y) * size.y); // the film counts from the bottom
    std::optional<float> distance = tracer.focusDistanceAt(filmPos);
    if (!distance) return std::nullopt;
    const SceneRange& range = ranges::kFocusDistance;
    float focus = std::clamp(*distance, std::nextafter(static_cast<float>(range.lo), 1.0f), static_cast<float>(range.hi));
    model_.scene.camera.focusDistance = focus;
    model_.pendingChanges |= ViewerModel::kCameraChanged;
    return focus;
}

std::optional<glm::ivec2> ViewerSession::pixelAt(glm::vec2 imageFraction) const {
    if (renderSize_.x <= 0 || renderSize_.y <= 0) return std::nullopt;
    glm::ivec2 pixel(glm::floor(imageFraction * glm::vec2(renderSize_)));
    return glm::clamp(pixel, glm::ivec2(0), renderSize_ - 1); // the far edge (fraction 1) is the last pixel
}

void ViewerSession::togglePinnedPixel(glm::ivec2 pixel) {
    if (model_.pinnedPixel == pixel) model_.pinnedPixel.reset();
    else pinPixel(pixel);
}

void ViewerSession::pinPixel(glm::ivec2 pixel) {
    model_.pinnedPixel = pixel;
    pixelProbe_ = PixelProbe{}; // a new pin: probed under the camera as it is now
}

void ViewerSession::restorePinnedCamera() {
    if (!model_.pinnedPixel || pixelProbe_.restartCount < 0) return;
    model_.scene.camera = pixelProbe_.camera;
    model_.pendingChanges |= ViewerModel::kCameraChanged;
}

ViewerSession::Side ViewerSession::sideOf(glm::ivec2 pixel) const {
    if (!comparing() || renderSize_.x <= 0) return Side::Left;
    PixelRect area = imageRect(); // the pixel's place on screen, zoomed and panned
    float centre = static_cast<float>(area.origin.x) +
                   (static_cast<float>(pixel.x) + 0.5f) / static_cast<float>(renderSize_.x) * static_cast<float>(area.size.x);
    return centre < static_cast<float>(dividerX()) ? Side::Left : Side::Right;
}

std::optional<PixelInspection> ViewerSession::inspectPinnedPixel() {
    if (!model_.pinnedPixel) {
        pixelProbe_ = PixelProbe{}; // pinning the same pixel again is a new pin
        return std::nullopt;
    }
    glm::ivec2 pixel = *model_.pinnedPixel;
    Side side = sideOf(pixel);
    PathTracer& tracer = *view(side).tracer;
    glm::ivec2 size = tracer.imageSize();
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= size.x || pixel.y >= size.y) return std::nullopt;
    PixelInspection inspection;
    inspection.pixel = pixel;
    inspection.imageSize = size;
    inspection.comparing = comparing();
    inspection.rightSide = side == Side::Right;
    const DisplaySettings display = displaySettings(side);
    inspection.reading = tracer.readPixel(pixel, display); // its displayed colour is the denoised one where shown
    if (display.denoised && tracer.hasDenoised()) {
        inspection.denoised = tracer.readDenoisedPixel(pixel);
        inspection.denoisedSamples = tracer.denoisedSampleCount();
    }
    const CameraDesc& camera = model_.scene.camera;
    const bool newPin = pixelProbe_.pixel != pixel || pixelProbe_.side != side || pixelProbe_.restartCount < 0;
    // A scene edit under the pin's camera may change what the pixel shows: probe again. After a
    // camera move the tracer's rays are another camera's, and the pin keeps what it showed.
    // (Only once update() has given the tracer the model's camera: until then its rays are the last frame's.)
    const bool sceneChangedUnderPin = pixelProbe_.restartCount != tracer.restartCount() && sameView(pixelProbe_.camera, camera) &&
                                      (model_.pendingChanges & ViewerModel::kCameraChanged) == 0;
    if (newPin || sceneChangedUnderPin) {
        // The pinhole ray through the pixel's centre; the film counts rows from the bottom.
        glm::vec2 filmPos(static_cast<float>(pixel.x) + 0.5f, static_cast<float>(size.y - pixel.y) - 0.5f);
        pixelProbe_ = PixelProbe{pixel, side, tracer.restartCount(), camera, tracer.probeSurface(filmPos),
                                 tracer.probeCameraRayMedia(filmPos)};
    }
    inspection.hit = pixelProbe_.hit;
    inspection.media = pixelProbe_.media;
    inspection.pinnedCamera = pixelProbe_.camera;
    inspection.cameraMoved = !sameView(pixelProbe_.camera, camera);
    return inspection;
}

// Compared as the file would hold them, so that an edit counts exactly when saving would change
// the file, and a field the file does not keep (one the material's type does not use) does not.
// Materials a glTF file made are in it too, as overrides in the file's reference.
bool ViewerSession::hasUnsavedEdits() const {
    if (carriedSceneUnsaved_) return true; // the image holds it, no file does
    try {
        return sceneToJson(model_.scene) != sceneToJson(model_.fileScene);
    } catch (const std::exception&) { // a model no file can hold is certainly not the file's
        return true;
    }
}

std::vector<std::string> ViewerSession::unsavedEdits() const {
    const Scene& file = model_.fileScene;
    const Scene& edited = model_.scene;
    std::vector<std::string> kinds;
    try {
        const std::string fileJson = sceneToJson(file);
        if (sceneToJson(edited) == fileJson) {
            if (carriedSceneUnsaved_) kinds.push_back("scene"); // all of it: the image holds it, no file does
            return kinds;
        }
        // Each kind alone on the file's scene: does it change what the file would hold?
        auto differs = [&](const char* kind, auto copyPart) {
            Scene partial = file;
            copyPart(partial);
            if (sceneToJson(partial) != fileJson) kinds.push_back(kind);
        };
        differs("materials", [&](Scene& s) { s.materials = edited.materials; });
        differs("lights", [&](Scene& s) { s.lights = edited.lights; });
        differs("camera", [&](Scene& s) { s.camera = edited.camera; });
        differs("environment", [&](Scene& s) {
            s.environment = edited.environment;
            s.environmentMap = edited.environmentMap;
            s.environmentIntensity = edited.environmentIntensity;
            s.environmentRotationDeg = edited.environmentRotationDeg;
        });
        if (kinds.empty()) kinds.push_back("scene"); // nothing the UI edits, yet not the file
    } catch (const std::exception&) { // a model no file can hold
        if (kinds.empty()) kinds.push_back("scene");
    }
    return kinds;
}

void ViewerSession::saveSceneAs(const std::filesystem::path& path) {
    saveScene(model_.scene, path);
    model_.scene.path = path;
    model_.fileScene = model_.scene;
    carriedSceneUnsaved_ = false;
    saveTarget_ = path.string();
    watchFiles();
}

bool ViewerSession::saveReplacesAnotherFile(const std::filesystem::path& path) const {
    std::error_code error;
    if (!std::filesystem::exists(path, error)) return false;
    const std::filesystem::path& own = model_.fileScene.path;
    return own.empty() || !std::filesystem::equivalent(path, own, error);
}

void ViewerSession::writeImage(Side side, const std::filesystem::path& path) {
    PathTracer& tracer = *view(side).tracer;
    if (tracer.sampleCount() == 0) throw std::runtime_error("nothing rendered yet: wait for a sample");
    syncDenoise(); // the model as it is now, even before this frame's update
    // A saved image is of every sample there is, whatever denoise the frames had finished.
    if (showsDenoised(side)) tracer.updateDenoised();
    const bool denoised = showsDenoised(side) && tracer.hasDenoised();
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    if (extension == ".pfm") {
        writePfm(path, denoised ? tracer.readDenoised() : tracer.readMean());
    } else if (extension == ".exr") {
        // As `ptview render --denoise` writes it (RenderCommand.cpp, exrWithAovs): RGB is the
        // image shown, the raw mean follows as the layer "raw.".
        ExrImage exr;
        const ImageRgbF mean = tracer.readMean();
        exr.width = mean.width;
        exr.height = mean.height;
        if (denoised) {
            exr.addRgb(tracer.readDenoised());
            exr.addRgb(mean, "raw.");
        } else {
            exr.addRgb(mean);
        }
        exr.metadata = provenance(side);
        writeExr(path, exr, ExrPixelType::Float);
    } else {
        writePng(path, tracer.readToneMapped(displaySettings(side)), provenance(side));
    }
}

ImageMetadata ViewerSession::provenance(Side side) const {
    const PathTracer& tracer = *view(side).tracer;
    // The denoiser as it made the image: on only where the side shows a denoised image, so that
    // opening the image again (`ptview shot.png`, --from) turns it on exactly then.
    DenoiseSettings denoise = model_.denoise;
    denoise.enabled = showsDenoised(side) && tracer.hasDenoised();
    DisplaySettings display = displaySettings(side);
    display.denoised = denoise.enabled;
    RenderRecipe recipe{tracer.settings(), display, tracer.sampleCount(), tracer.imageSize(), tracer.backend(),
                        programOptions_.allFeatures, denoise, {}, std::nullopt};
    // An adaptive image says so: `render --from` it samples adaptively to the same threshold, capped at its spp.
    if (const View& v = view(side); v.adaptive) recipe.noiseThreshold = static_cast<float>(v.adaptive->noiseThreshold());
    if (display.toneMapper == ToneMapper::Ocio) recipe.ocio = model_.ocio;
    return provenanceMetadata(model_.scene, recipe, glDeviceDescription());
}

std::vector<std::filesystem::path> ViewerSession::saveScreenshots(const std::filesystem::path& directory) {
    std::filesystem::create_directories(directory);
    std::string stem = screenshotStem(model_.scene);
    // Two saves within a second get distinct names.
    for (int n = 2; std::filesystem::exists(directory / (stem + ".png")) ||
                    std::filesystem::exists(directory / (stem + "-left.png"));
         ++n)
        stem = screenshotStem(model_.scene) + "-" + std::to_string(n);
    std::vector<std::filesystem::path> written;
    auto save = [&](Side side, const std::string& name) {
        for (const char* extension : {".png", ".pfm", ".exr"}) {
            std::filesystem::path path = directory / (name + extension);
            writeImage(side, path);
            written.push_back(path);
        }
    };
    if (comparing()) {
        save(Side::Left, stem + "-left");
        save(Side::Right, stem + "-right");
    } else {
        save(Side::Left, stem);
    }
    return written;
}

// ---- per frame -------------------------------------------------------------------------------

void ViewerSession::watchFiles() {
    std::vector<std::filesystem::path> files = shaderFiles(shaderDir_);
    if (!model_.fileScene.path.empty()) files.push_back(model_.fileScene.path);
    if (!model_.scene.environmentMap.empty()) files.push_back(model_.scene.environmentMap);
    watcher_.watch(files);
}

void ViewerSession::pollFiles() {
    std::vector<std::filesystem::path> changed = watcher_.poll();
    if (changed.empty()) return;
    bool sceneChanged = false, mapChanged = false, shaderChanged = false;
    for (const std::filesystem::path& file : changed) {
        if (file == model_.fileScene.path)
            sceneChanged = true;
        else if (file == model_.scene.environmentMap)
            mapChanged = true;
        else
            shaderChanged = true;
    }
    if (sceneChanged)
        reloadScene();
    else if (mapChanged && setEnvironmentMap(model_.scene.environmentMap))
        ++reloadCount_;
    if (shaderChanged) reloadShaders();
}

void ViewerSession::reloadShaders() {
    ++reloadCount_;
    try {
        left_.tracer->reloadShaders();
        if (right_) right_->tracer->reloadShaders();
        model_.shaderError.clear();
        model_.notice = "shaders reloaded from " + shaderDir_.string();
    } catch (const ShaderError& e) {
        model_.shaderError = e.what();
    }
}

bool ViewerSession::setOcioView(const OcioRequest& request) {
    try {
        std::shared_ptr<const OcioView> view;
        std::vector<OcioDisplayViews> displays;
        if (!request.config.empty()) {
            view = std::make_shared<const OcioView>(request.config, request.display, request.view);
            displays = OcioView::displaysAndViews(request.config);
        }
        left_.tracer->setOcioView(view);
        if (right_) right_->tracer->setOcioView(view);
        ocioView_ = view;
        ocioDisplays_ = std::move(displays);
        model_.ocioError.clear();
        if (view) {
            model_.ocio = {request.config, view->display(), view->view()};
            model_.display.toneMapper = ToneMapper::Ocio;
            model_.notice = "showing the OpenColorIO view " + view->label();
        } else {
            model_.ocio = {};
            if (model_.display.toneMapper == ToneMapper::Ocio) model_.display.toneMapper = ToneMapper::Reinhard;
        }
        return true;
    } catch (const OcioError& e) {
        model_.ocioError = e.what();
    } catch (const ShaderError& e) {
        model_.ocioError = request.config + ": OpenColorIO's shader for this view does not compile: " + e.what();
        left_.tracer->setOcioView(ocioView_); // the left may have taken it before the right refused
    }
    return false;
}

void ViewerSession::setImageArea(PixelRect area) {
    imageArea_ = area;
}

RenderSettings ViewerSession::effectiveSettings(const RenderSettings& settings) const {
    RenderSettings effective = settings;
    effective.seed = model_.settings.seed; // both sides of a comparison see the same random numbers
    effective.debugView = model_.settings.debugView;
    if (model_.targetSamples > 0) effective.sampleBudget = static_cast<std::uint32_t>(model_.targetSamples);
    return effective;
}

void ViewerSession::syncView(View& view, const RenderSettings& settings, unsigned changes) {
    PathTracer& tracer = *view.tracer;
    if (changes & ViewerModel::kSceneChanged) {
        tracer.setScene(model_.scene, model_.environmentMap.get());
        view.cost.forget();
        view.previewCost.forget();
    } else if (changes & ViewerModel::kMaterialsChanged) {
        tracer.setMaterials(model_.scene.materials);
    }
    if (changes & ViewerModel::kCameraChanged) tracer.setCamera(model_.scene.camera);
    if (changes & ViewerModel::kRestart) tracer.restart();
    if (tracer.imageSize() != renderSize_) {
        tracer.setImageSize(renderSize_);
        view.cost.forget();
        view.previewCost.forget();
    }
    if (tracer.settings() != settings || tracer.backend() != model_.backend) { // costs differ
        view.cost.forget();
        view.previewCost.forget();
    }
    tracer.setSettings(settings);
    tracer.setBackend(model_.backend);
    trackRestart(view);
}

glm::ivec2 ViewerSession::wantedRenderSize() const {
    glm::vec2 scaled = glm::vec2(imageArea_.size) * model_.resolutionScale;
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    return glm::clamp(glm::ivec2(glm::round(scaled)), glm::ivec2(1), glm::ivec2(maxSize));
}

// The render follows the image area's size only when that loses nothing: while no view has a
// complete sample (once the size has stopped changing for kResizeSettleSeconds, so a window being
// dragged restarts once, not every frame), or when the accumulation starts over anyway (an edit,
// a camera move, a setting, a new resolution scale, R). Otherwise an image survives Tab and
// resizes, displayed scaled in its own aspect ratio (displayArea) until the user asks.
void ViewerSession::followImageArea(unsigned changes) {
    glm::ivec2 wanted = wantedRenderSize();
    if (wanted != wantedSize_) wantedSize_ = wanted, wantedSince_ = Clock::now();
    if (wanted == renderSize_) return;
    auto settingsChange = [&](const View& view, const RenderSettings& settings) {
        return view.tracer->settings() != effectiveSettings(settings) || view.tracer->backend() != model_.backend;
    };
    bool restarting = (changes & (ViewerModel::kSceneChanged | ViewerModel::kMaterialsChanged |
                                  ViewerModel::kCameraChanged | ViewerModel::kRestart)) != 0 ||
                      model_.resolutionScale != followedScale_ || settingsChange(left_, model_.settings) ||
                      (right_ && settingsChange(*right_, model_.compare.right)) || (twoRendersWanted() && !right_);
    bool nothingRendered = left_.tracer->sampleCount() == 0 && (!right_ || right_->tracer->sampleCount() == 0);
    bool settled = secondsSince(wantedSince_) >= kResizeSettleSeconds;
    if (renderSize_.x == 0 || restarting || (nothingRendered && settled)) {
        model_.pinnedPixel.reset(); // its numbers would name another place of the picture
        renderSize_ = wanted;
        followedScale_ = model_.resolutionScale;
    }
}

PixelRect ViewerSession::displayArea() const {
    if (renderSize_.x <= 0 || renderSize_.y <= 0 || imageArea_.size.x <= 0 || imageArea_.size.y <= 0) return imageArea_;
    // The render's aspect ratio, as large as fits, centred: bars where the shapes differ.
    glm::vec2 area(imageArea_.size);
    float scale = std::min(area.x / static_cast<float>(renderSize_.x), area.y / static_cast<float>(renderSize_.y));
    glm::ivec2 size = glm::clamp(glm::ivec2(glm::round(glm::vec2(renderSize_) * scale)), glm::ivec2(1), imageArea_.size);
    return PixelRect{imageArea_.origin + (imageArea_.size - size) / 2, size};
}

void ViewerSession::update() {
    setPatternTarget();
    unsigned changes = model_.pendingChanges | restartOnCompare();
    model_.pendingChanges = 0;
    followImageArea(changes);
    if (twoRendersWanted() && !right_) {
        // A first comparison shows something worth comparing: MIS against what the left side has.
        CompareSettings& compare = model_.compare;
        if (compare.right == model_.settings)
            compare.right.integrator = model_.settings.integrator == Integrator::Mis ? Integrator::Naive : Integrator::Mis;
        right_ = std::make_unique<View>();
        right_->tracer = std::make_unique<PathTracer>(makePathTracer(model_.scene, model_.environmentMap.get(),
                                                                     PathTracerOptions{programOptions_.allFeatures, model_.backend},
                                                                     RenderSettings{}, shaderDir_));
        right_->tracer->setPreviewEnabled(true);
        if (ocioView_) right_->tracer->setOcioView(ocioView_); // compiled once already, on the left
    }
    try {
        syncView(left_, effectiveSettings(model_.settings), changes);
        if (right_) syncView(*right_, effectiveSettings(model_.compare.right), changes);
    } catch (const EnvironmentMapError& e) { // a map larger than this GPU's textures
        setEnvironmentMap({}); // the constant colour instead, and say why
        model_.sceneError = e.what();
    }
    syncAdaptive();
    syncDenoise();
    syncOtherImages();
}

// A new target (or none) restarts: pixels stopped for one threshold are not those another would
// stop, and turning it off lets every pixel sample again. Any other restart (an edit, a camera
// move, a resize) starts the checks over too.
void ViewerSession::syncAdaptive() {
    const float wanted = model_.targetErrorOn ? model_.targetError : 0.0f;
    PathTracer& tracer = *left_.tracer;
    if (wanted != seenTargetError_) {
        seenTargetError_ = wanted;
        left_.adaptive.reset();
        tracer.restart();
        // Adaptive against uniform at equal time starts both sides together.
        if (comparesTwoRenders()) {
            right_->tracer->restart();
            trackRestart(*right_);
        }
    }
    if (wanted > 0.0f && (!left_.adaptive || left_.adaptiveRestartCount != tracer.restartCount())) {
        left_.adaptive = std::make_unique<AdaptiveSampler>(tracer, wanted); // restarts the tracer
        left_.adaptiveRestartCount = tracer.restartCount();
        left_.adaptiveChecks = 0;
    }
    trackRestart(left_);
}

bool ViewerSession::showsDenoised(Side side) const {
    if (model_.settings.debugView != DebugView::Radiance) return false; // a feature, not light: no noise to take out
    if (splitsRawAndDenoised()) return side == Side::Right;
    if (side == Side::Right && comparesTwoRenders()) return model_.compare.rightDenoised;
    return model_.denoise.enabled;
}

DisplaySettings ViewerSession::displaySettings(Side side) const {
    DisplaySettings display = model_.display;
    display.denoised = showsDenoised(side);
    if (splitsImageAndView() && side == Side::Left) display.view = DisplayView::Image;
    return display;
}

// Each tracer denoises when a side shown from it wants the denoised image; the settings change
// nothing of the accumulation, so this never restarts.
void ViewerSession::syncDenoise() {
    DenoiseSettings left = model_.denoise;
    left.enabled = showsDenoised(Side::Left) || (splitsRawAndDenoised() && showsDenoised(Side::Right));
    left_.tracer->setDenoise(left);
    if (right_) {
        DenoiseSettings right = model_.denoise;
        right.enabled = comparesTwoRenders() && showsDenoised(Side::Right);
        right_->tracer->setDenoise(right);
    }
}

// Grid and stratified chosen without a target would run on past no end, showing a partial pattern
// (SamplerMode.h); the target stops them where the pattern is complete. Also for a sampler given
// on the command line, which is the user's choice too. A target the user set, or cleared after
// this, stays theirs.
void ViewerSession::setPatternTarget() {
    SamplerMode samplers[2] = {model_.settings.sampler, model_.compare.right.sampler};
    bool chosen = false;
    for (int side = 0; side < 2; ++side) {
        bool used = side == 0 || model_.compare.enabled;
        if (used && samplers[side] != seenSampler_[side] && needsPatternTarget(samplers[side])) chosen = true;
        if (used) seenSampler_[side] = samplers[side];
    }
    if (!chosen || model_.targetSamples != 0) return;
    model_.targetSamples = kPatternTargetSamples;
    model_.notice = "target set to " + std::to_string(kPatternTargetSamples) +
                    " spp: grid and stratified patterns are complete only at the target";
}

// Equal time must mean equal time from the first frame: turning the split view on starts both
// sides afresh, not the left one with a head start.
unsigned ViewerSession::restartOnCompare() {
    bool turnedOn = twoRendersWanted() && !seenCompare_; // a raw | denoised split is of one render: nothing to restart
    seenCompare_ = twoRendersWanted();
    return turnedOn ? ViewerModel::kRestart : 0u;
}

void ViewerSession::trackRestart(View& view) {
    if (view.tracer->restartCount() == view.seenRestartCount) return;
    view.seenRestartCount = view.tracer->restartCount();
    view.renderSeconds = 0.0;
    view.error = ErrorEstimate{};
    view.estimatedSamples = 0;
    view.errorHistory.clear();
    view.earlierMeans.clear();
    view.trueError.reset();
    view.trueErrorHistory.clear();
    view.denoisedTrueError.reset();
}

bool ViewerSession::wantsSamples(const View& view, int passesThisFrame) const {
    if (model_.paused) return false;
    if (model_.targetSamples > 0 && view.tracer->sampleCount() >= model_.targetSamples) return false;
    if (view.adaptive && view.adaptive->finished()) return false;
    // Adaptive against uniform at equal time: once the main view's adaptive sampling stopped, the
    // split view's other render stops at the same GPU time, so the two show what equal cost buys.
    if (&view != &left_ && model_.compare.equalTime && left_.adaptive && left_.adaptive->finished() &&
        view.renderSeconds >= left_.renderSeconds)
        return false;
    return model_.maxSamplesPerFrame <= 0 || passesThisFrame < model_.maxSamplesPerFrame;
}

bool ViewerSession::accumulating() const {
    bool left = wantsSamples(left_, 0);
    return comparesTwoRenders() ? left || wantsSamples(*right_, 0) : left; // a raw | denoised split is one render
}

double ViewerSession::renderFrame(double budgetSeconds) {
    View* views[2] = {&left_, comparesTwoRenders() ? right_.get() : nullptr};
    int passes[2] = {0, 0};
    Clock::time_point frameStart = Clock::now();
    // A stale denoised image gets its share of the frame: bands of the denoise's passes after the
    // tracing (PathTracer::advanceDenoised), so a denoise spreads over frames as a sample pass
    // does and no frame waits for a whole one. While samples accumulate the share is
    // kDenoiseShare; once they stop, the denoise takes the frame.
    double denoiseSeconds[2] = {0.0, 0.0};
    for (int i = 0; i < 2; ++i) {
        if (!views[i] || !denoiseStale(*views[i])) continue;
        denoiseSeconds[i] = wantsSamples(*views[i], 0) ? kDenoiseShare * budgetSeconds : budgetSeconds;
        budgetSeconds -= denoiseSeconds[i];
    }
    bool worked = false;
    for (;;) {
        // The view that is behind goes next: in GPU time, or in samples (with the pass in
        // progress counted as a fraction).
        int next = -1;
        double behind = 0.0;
        for (int i = 0; i < 2; ++i) {
            if (!views[i] || !wantsSamples(*views[i], passes[i])) continue;
            const PathTracer& tracer = *views[i]->tracer;
            double progress = model_.compare.equalTime
                                  ? views[i]->renderSeconds
                                  : tracer.sampleCount() + double(tracer.nextRow()) / tracer.imageSize().y;
            if (next < 0 || progress < behind) next = i, behind = progress;
        }
        if (next < 0) break;
        double remaining = budgetSeconds - secondsSince(frameStart);
        View& chosen = *views[next];
        PathTracer& tracer = *chosen.tracer;
        // Until the full size has a sample, the preview's passes first: an image within a frame
        // or two however large the window (PathTracer::setPreviewEnabled).
        bool preview = tracer.previewWanted();
        TileCost& cost = preview ? chosen.previewCost : chosen.cost;
        if (worked && (remaining <= 0.0 || cost.rowOverruns(remaining))) break;
        int rowsLeft = preview ? tracer.previewLevelSize().y - tracer.previewNextRow() : tracer.imageSize().y - tracer.nextRow();
        // The coarsest level's first pass (a thousand pixels or so) goes in one piece, whatever
        // the budget: a loaded machine that gets a row per frame would otherwise take a frame per
        // row before anything shows.
        int rows = preview && !tracer.previewStarted() ? rowsLeft : cost.rowsFitting(remaining, rowsLeft);
        Clock::time_point tileStart = Clock::now();
        bool passDone = preview ? tracer.renderPreviewRows(rows) : tracer.renderRows(rows);
        glFinish(); // the time of this tile's GPU work, not of its submission
        double seconds = secondsSince(tileStart);
        cost.record(rows, seconds);
        chosen.renderSeconds += seconds;
        worked = true;
        if (passDone && !preview) {
            ++passes[next];
            // Only the frame whose pass reaches a check reads the image back.
            if (chosen.adaptive && chosen.adaptive->checkIfDue()) ++chosen.adaptiveChecks;
        }
    }
    for (int i = 0; i < 2; ++i)
        if (denoiseSeconds[i] > 0.0) denoise(*views[i], denoiseSeconds[i]);
    double seconds = secondsSince(frameStart);
    for (View* v : views)
        if (v) updateErrorEstimate(*v);
    return seconds;
}

bool ViewerSession::denoiseStale(const View& view) const {
    const PathTracer& tracer = *view.tracer;
    return tracer.denoiseSettings().enabled && tracer.sampleCount() > 0 && !tracer.denoisedUpToDate();
}

bool ViewerSession::denoisePending() const {
    return denoiseStale(left_) || (comparesTwoRenders() && denoiseStale(*right_));
}

void ViewerSession::denoise(View& view, double seconds) {
    PathTracer& tracer = *view.tracer;
    try {
        // At least one band, so a denoise always progresses; then as many as the time allows.
        for (bool first = true;; first = false) {
            const int rowsLeft = tracer.denoiseRowsLeft();
            if (rowsLeft == 0 || (!first && view.denoiseCost.rowOverruns(seconds))) break;
            const int rows = view.denoiseCost.rowsFitting(seconds, rowsLeft);
            Clock::time_point start = Clock::now();
            const bool finished = tracer.advanceDenoised(rows);
            glFinish(); // the time of the GPU work, not of its submission
            const double spent = secondsSince(start);
            view.denoiseCost.record(rows, spent);
            seconds -= spent;
            if (finished || seconds <= 0.0) break;
        }
    } catch (const std::exception& e) { // its shaders edited on disk, a target this GPU refuses: the raw image instead
        model_.shaderError = std::string("denoiser: ") + e.what();
        model_.denoise.enabled = false;
        model_.compare.rightDenoised = false;
        if (splitsRawAndDenoised()) model_.compare.enabled = false;
        syncDenoise();
    }
}

namespace {

// "percent" with up to three significant digits: 0.0098 -> "0.98%".
std::string percentText(double fraction) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g%%", 100.0 * fraction);
    return text;
}

} // namespace

std::string adaptiveStopNote(const AdaptiveSampler& sampler) {
    if (sampler.reachedThreshold())
        return "stopped: estimated error " + percentText(relativeError(sampler.estimate().relativeMse)) + " <= " +
               percentText(sampler.noiseThreshold());
    if (sampler.allStopped()) return "stopped: every pixel stopped";
    return "";
}

void ViewerSession::updateErrorEstimate(View& view) {
    int samples = view.tracer->sampleCount();
    if (samples < 2 || samples == view.estimatedSamples) return;
    if (secondsSince(view.lastEstimate) < kErrorEstimateIntervalSeconds) return;
    view.lastEstimate = Clock::now();
    view.estimatedSamples = samples;
    view.estimatedSeconds = view.renderSeconds;
    PixelStatistics statistics = view.tracer->readStatistics();
    recordErrorEstimate(view, statistics);
    const ImageRgbF* reference = model_.reference.get();
    if (reference && reference->width == statistics.mean.width && reference->height == statistics.mean.height) {
        view.trueError = compareToReference(statistics.mean, *reference);
        if (view.trueErrorHistory.size() == kErrorHistoryLength) view.trueErrorHistory.erase(view.trueErrorHistory.begin());
        view.trueErrorHistory.emplace_back(static_cast<float>(view.renderSeconds), static_cast<float>(view.trueError->relativeMse));
        // The denoised image is judged against the same reference, so the two lines tell what
        // the filter's bias buys in noise.
        const PathTracer& tracer = *view.tracer;
        if (tracer.denoiseSettings().enabled && tracer.hasDenoised()) {
            view.denoisedTrueError = compareToReference(tracer.readDenoised(), *reference);
        } else {
            view.denoisedTrueError.reset();
        }
    } else {
        view.trueError.reset();
        view.denoisedTrueError.reset();
    }
}

void ViewerSession::recordErrorEstimate(View& view, const PixelStatistics& statistics) {
    // The latest earlier mean at half the samples or fewer; those before it are never needed again.
    std::vector<std::pair<int, ImageRgbF>>& earlier = view.earlierMeans;
    auto usable = std::find_if(earlier.rbegin(), earlier.rend(),
                               [&](const auto& entry) { return 2 * entry.first <= statistics.sampleCount; });
    if (usable != earlier.rend()) {
        earlier.erase(earlier.begin(), usable.base() - 1);
        view.error = estimateError(statistics, earlier.front().second, earlier.front().first,
                                   view.tracer->settings().sampler);
    } else {
        view.error = estimateError(statistics, ImageRgbF(), 0, view.tracer->settings().sampler);
    }
    // Kept at counts that at least double, so a handful of images cover any run.
    if (earlier.empty() || statistics.sampleCount >= 2 * earlier.back().first)
        earlier.emplace_back(statistics.sampleCount, statistics.mean);
    if (!view.error.reliable) return;
    if (view.errorHistory.size() == kErrorHistoryLength) view.errorHistory.erase(view.errorHistory.begin());
    view.errorHistory.emplace_back(static_cast<float>(view.renderSeconds), static_cast<float>(view.error.relativeMse));
}

int ViewerSession::dividerX() const {
    float fraction = std::clamp(model_.compare.dividerFraction, 0.0f, 1.0f);
    PixelRect area = viewArea();
    return area.origin.x + static_cast<int>(std::round(fraction * static_cast<float>(area.size.x)));
}

void ViewerSession::display() const {
    PixelRect area = viewArea();
    PixelRect image = imageRect();
    if (!comparing()) {
        left_.tracer->display(image, displaySettings(Side::Left), area);
        return;
    }
    int divider = dividerX();
    PixelRect leftClip{area.origin, {divider - area.origin.x, area.size.y}};
    PixelRect rightClip{{divider, area.origin.y}, {area.origin.x + area.size.x - divider, area.size.y}};
    if (leftClip.size.x > 0) left_.tracer->display(image, displaySettings(Side::Left), leftClip);
    if (rightClip.size.x > 0) view(Side::Right).tracer->display(image, displaySettings(Side::Right), rightClip);
    // The divider: two pixels of white, drawn by clearing a scissored column.
    glEnable(GL_SCISSOR_TEST);
    glScissor(divider - 1, area.origin.y, 2, area.size.y);
    glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
}

ViewerSession::ViewStats ViewerSession::stats(Side side) const {
    const View& v = view(side);
    ViewStats stats;
    stats.samples = v.tracer->sampleCount();
    stats.renderSeconds = v.renderSeconds;
    glm::ivec2 size = v.tracer->imageSize();
    if (v.renderSeconds > 0.0)
        stats.samplesPerSecond = double(size.x) * size.y * (stats.samples + double(v.tracer->nextRow()) / size.y) / v.renderSeconds;
    stats.errorSamples = v.estimatedSamples;
    stats.errorSeconds = v.estimatedSeconds;
    stats.error = v.error;
    stats.errorHistory = v.errorHistory;
    stats.trueError = v.trueError;
    stats.trueErrorHistory = v.trueErrorHistory;
    stats.denoised = showsDenoised(side);
    if (stats.denoised) {
        stats.denoisedSamples = v.tracer->denoisedSampleCount();
        stats.denoisedTrueError = v.denoisedTrueError;
    }
    if (v.adaptive) {
        const AdaptiveSampler& sampler = *v.adaptive;
        ViewStats::Adaptive adaptive;
        adaptive.targetError = sampler.noiseThreshold();
        adaptive.checks = v.adaptiveChecks;
        adaptive.estimate = sampler.estimate();
        adaptive.samples = sampler.sampleCounts();
        adaptive.finished = sampler.finished();
        adaptive.note = adaptiveStopNote(sampler);
        stats.adaptive = adaptive;
    }
    return stats;
}

const RenderSettings& ViewerSession::settings(Side side) const {
    return view(side).tracer->settings();
}

const ViewerSession::TracedPaths& ViewerSession::tracePaths(glm::ivec2 pixel, int count) {
    update(); // the tracer renders what the user sees
    if (!pathRecorder_) pathRecorder_ = std::make_unique<PathRecorder>();
    PathTracer& tracer = *left_.tracer;
    TracedPaths traced;
    traced.paths = pathRecorder_->record(tracer, pixel, count);
    traced.pixel = pixel;
    traced.imageSize = tracer.imageSize();
    traced.settings = tracer.settings();
    traced.camera = model_.scene.camera;
    tracedPaths_ = std::move(traced);
    return *tracedPaths_;
}

} // namespace ptview
