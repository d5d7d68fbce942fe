#pragma once
// The viewer without its window: the model the user edits, the path tracer(s) that render it,
// and the actions the panels, keys and scripts share (open, reload, screenshots). Each frame the
// window calls pollFiles, update, renderFrame and display. It needs a current OpenGL context but
// knows nothing about GLFW or ImGui, so tests can drive it headless.

#include <ptview/model/EditHistory.h>
#include <ptview/metrics/ErrorEstimate.h>
#include <ptview/metrics/ErrorMetrics.h>
#include <ptview/model/FileWatcher.h>
#include <ptview/io/ImageMetadata.h>
#include <ptview/tracer/PathRecorder.h>
#include <ptview/tracer/PathTracer.h>
#include <ptview/session/PixelInspection.h>
#include <ptview/model/SceneInput.h>
#include <ptview/session/TileCost.h>
#include <ptview/tracer/AdaptiveSampler.h>
#include <ptview/model/ViewerModel.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ptview {

// Why adaptive sampling stopped, for the Render and Stats panels: "stopped: estimated error 0.98%
// <= 1%", "stopped: every pixel stopped", or "" while it goes on.
std::string adaptiveStopNote(const AdaptiveSampler& sampler);

class ViewerSession {
public:
    // Path tracing per displayed frame when the caller does not say: the viewer passes what is
    // left of its ~33 ms frame after the display pass and the UI.
    static constexpr double kDefaultTracingSeconds = 0.030;
    // The share of a frame's budget a stale denoised image gets while samples accumulate: the
    // rest goes on samples, which the denoised image needs too.
    static constexpr double kDenoiseShare = 0.25;

    enum class Side { Left, Right }; // Left is the only view outside compare mode

    // What the Stats panel shows for one view.
    struct ViewStats {
        int samples = 0;
        double renderSeconds = 0.0; // GPU time spent on the current accumulation
        double samplesPerSecond = 0.0;
        // The error estimate and the true error measure the raw accumulation (readStatistics),
        // whatever the view shows. They are measured about once a second, not every frame: at
        // errorSamples spp, errorSeconds into the rendering, which the panels print beside them
        // (a figure beside `samples` alone would pass an old count's error off as the current one).
        int errorSamples = 0;
        double errorSeconds = 0.0;
        ErrorEstimate error;
        // (render seconds, estimated relative MSE) once a second or so while the estimate is
        // reliable, for the error-vs-time plot.
        std::vector<std::pair<float, float>> errorHistory;
        // Against the reference image, when one of the render's size is loaded.
        std::optional<ErrorMetrics> trueError;
        std::vector<std::pair<float, float>> trueErrorHistory; // (seconds, relative MSE)
        // Whether the view shows the denoised image (showsDenoised), of how many samples, and,
        // with a reference, the true error of that image too (measured with the raw one's).
        bool denoised = false;
        int denoisedSamples = 0;
        std::optional<ErrorMetrics> denoisedTrueError;
        // Adaptive sampling (ViewerModel::targetErrorOn; the main view only): the state at its
        // last check. `adaptiveNote` says why it stopped ("" while it goes on).
        struct Adaptive {
            double targetError = 0.0;
            int checks = 0;
            ErrorEstimate estimate;     // at the last check (AdaptiveSampler::estimate)
            SampleCountSummary samples; // each pixel's own count at the last check
            bool finished = false;
            std::string note;
        };
        std::optional<Adaptive> adaptive;
    };

    // Compiles the programs from shaderDir (throws ShaderError). Without a backend in `program`,
    // the tracer measures which is faster on this device (PathTracer::chooseBackend).
    ViewerSession(SceneInput input, const RenderSettings& settings, const DisplaySettings& display,
                  std::filesystem::path shaderDir, PathTracerOptions program = {});
    ~ViewerSession();

    ViewerModel& model() { return model_; }
    const ViewerModel& model() const { return model_; }

    // Actions. A file that cannot be read sets model().sceneError and changes nothing else.
    // Opening another scene starts the undo history afresh; opening the open scene's own file
    // again (Reload, discarding the edits) is a step that undo takes back.
    bool openScene(const std::filesystem::path& path);
    // Merges the file's changes with the user's edits (SceneMerge.h), and the undo history's
    // states the same way (EditHistory::rebase).
    bool reloadScene();
    bool setEnvironmentMap(const std::filesystem::path& path); // empty: none (the constant colour)
    // Loads a reference image (.pfm or .exr) for the true error; empty: none. A file that cannot be read
    // sets model().sceneError.
    bool setReference(const std::filesystem::path& path);
    // Loads the image the difference and other-image views compare the render with (.pfm or .exr,
    // finite, the render's size); empty: none (they use the reference). A file that cannot be
    // read, or of another size, sets model().sceneError, says why, and keeps the current one.
    bool setCompareImage(const std::filesystem::path& path);
    // The image a view compares the render with: the reference for the error map; the comparison
    // image, else the reference, for the difference views; null for the others or when none is loaded.
    std::shared_ptr<const ImageRgbF> otherImageFor(DisplayView view) const;
    // Why a side cannot show the view asked for (it shows the image instead), or "" when it can.
    std::string viewProblem(Side side) const;
    // Shows the image through an OpenColorIO display and view (empty: the config's defaults) and
    // picks ToneMapper::Ocio; an empty config removes the view. A config that does not load, or
    // lacks the display or view, sets model().ocioError and keeps the transform shown.
    bool setOcioView(const OcioRequest& request);
    // The loaded config's displays and their views (empty without one): what the Render panel offers.
    const std::vector<OcioDisplayViews>& ocioDisplays() const { return ocioDisplays_; }
    void resetCamera();                                          // to the scene file's camera
    // Click-to-focus: sets the camera's focus distance to the distance along the view direction of
    // the surface seen at `imageFraction` of the image (x right, y down from its top-left corner,
    // each in [0, 1]), found by a one-pixel GPU pass (PathTracer::focusDistanceAt). Returns that
    // distance, or nullopt (the camera unchanged) when nothing is there.
    std::optional<float> focusAt(glm::vec2 imageFraction);
    // The pixel inspector (ViewerModel::pinnedPixel). The render pixel (x from the left, y from
    // the top) at imageFraction of the image, as focusAt takes it; nullopt before there is a render.
    std::optional<glm::ivec2> pixelAt(glm::vec2 imageFraction) const;
    // The render pixel drawn at a framebuffer position (x right, y up), through the zoom and pan
    // (ImageZoom.h); nullopt off the image or outside the view.
    std::optional<glm::ivec2> pixelAtFramebuffer(glm::vec2 framebufferPos) const;
    // Where the render is drawn: the display area when fitting, else zoomed and panned about it
    // (possibly far larger than the window); and the part of the window it may cover (viewArea:
    // the display area when fitting, all the image area when zoomed).
    PixelRect imageRect() const;
    PixelRect viewArea() const;
    // Zoom (ImageZoom.h): to `scale` framebuffer pixels per render pixel about a framebuffer
    // position (the mouse pointer), or the view's centre; fit; pan by framebuffer pixels (x right, y up).
    void zoomImageTo(float scale, std::optional<glm::vec2> aboutFramebufferPos = std::nullopt);
    void zoomImageBySteps(int steps, std::optional<glm::vec2> aboutFramebufferPos = std::nullopt);
    void fitImage() { model_.zoom = ImageZoom{}; }
    void panImage(glm::vec2 framebufferDelta);
    // Alt+click: pins the pixel, or unpins it when it is the one pinned.
    void togglePinnedPixel(glm::ivec2 pixel);
    // Pins the pixel under the camera as it is now (`pin-pixel`, and the Pixel panel's "Re-pin
    // here" after a camera move): its first hit is probed afresh.
    void pinPixel(glm::ivec2 pixel);
    // The Pixel panel's "Back to the pinned camera": the camera the pixel was pinned under.
    void restorePinnedCamera();
    // Split view: the view whose numbers a pixel shows, by the side of the divider its centre is on.
    Side sideOf(glm::ivec2 pixel) const;
    // The pinned pixel's numbers now: one pixel read back from that side's accumulation (and from
    // its denoised image, where the side shows one), and the first hit. The hit is probed with
    // the camera of the pin and again only when the pixel or the side changed, or the scene
    // changed while the camera is still the pin's: a camera move keeps the pinned surface
    // (PixelInspection::cameraMoved says so). nullopt when none is pinned or it is outside the render.
    std::optional<PixelInspection> inspectPinnedPixel();
    // Whether the scene in memory differs from its file in anything the file holds, the camera
    // included (a view the user set up is work): what quitting or opening another scene would
    // throw away. A scene an image carried counts as edits until saved, unless the file it names
    // holds it as it is (SceneInput::carriedSceneIsInItsFile).
    bool hasUnsavedEdits() const;
    // The kinds of those edits, in this order: "materials" (those a glTF file made too),
    // "lights", "camera", "environment", and "scene" for anything else; empty when there are none.
    std::vector<std::string> unsavedEdits() const;
    // Writes the scene with the user's edits (atomically) and makes that file the scene's file,
    // the one hot reload watches, and the save target. Throws SceneError naming the file when it
    // cannot be written. Edits to materials a glTF file made are saved as overrides in the scene
    // file's reference to it (docs/scene-format.md, `gltf`).
    void saveSceneAs(const std::filesystem::path& path);
    // What Save writes to (the Materials panel's "Save scene as" field): the open scene's own
    // file, or what the user typed since it was opened. Opening a scene, or saving as another
    // file, makes that file the target.
    const std::string& saveTarget() const { return saveTarget_; }
    void setSaveTarget(std::string path) { saveTarget_ = std::move(path); }
    // Whether saving to path would replace a file other than the open scene's own, which the
    // viewer asks about first.
    bool saveReplacesAnotherFile(const std::filesystem::path& path) const;
    // Tone-mapped PNG, linear PFM and linear EXR of each view into directory, named after the scene and the
    // time; returns the files written. Throws std::runtime_error when nothing is rendered yet or
    // a file cannot be written.
    std::vector<std::filesystem::path> saveScreenshots(const std::filesystem::path& directory);
    // One image of a view: .png tone mapped as displayed, or .pfm or .exr (float) linear; the PNG and
    // EXR carry the view's provenance (Provenance.h: the scene with its edits and the settings).
    // Where the view shows the denoised image, it is first denoised up to the last sample, and
    // every format holds it: the EXR has it as RGB and the raw mean as the layer "raw." (as
    // `ptview render --denoise` writes). Throws as above.
    void writeImage(Side side, const std::filesystem::path& path);
    // What a PNG or EXR of a view carries to be rendered again (Provenance.h); the window's
    // screenshots carry the left view's.
    ImageMetadata provenance(Side side) const;

    // Undo and redo of the scene edits (docs/viewer.md, "Undo and redo"; EditHistory.h).
    // recordEdits makes what changed since the last step one step: the window calls it every
    // frame, with inProgress while a slider is held, a drag or a burst of wheel notches goes on or
    // a fly key is down, so that such an edit is one step; a script after every command. undo and
    // redo record first, then restore the scene's edits as they were before (after) the step and
    // flag what the renderer must redo (materials alone: kMaterialsChanged; the camera:
    // kCameraChanged; ...). An edit the history refused (one the scene format would not hold) is
    // what undo takes back first. They return false when there is nothing to do, or when the map
    // of the state cannot be read again (model().sceneError says so); model().notice says what
    // they did ("undid roughness of 'floor'", "nothing to undo").
    void recordEdits(bool inProgress = false);
    bool undo();
    bool redo();
    const EditHistory& history() const { return history_; }

    // Per frame, in this order.
    void pollFiles();                   // hot reload of the scene, its environment map and the shaders
    void setImageArea(PixelRect area);  // where the image goes in the window's framebuffer
    void update();                      // pushes model changes to the renderer(s)
    // Path traces for up to budgetSeconds (at least one tile of one row, so a frame always
    // progresses), measured with glFinish after each tile, then advances the denoise of each view
    // whose denoised image is stale by bands of rows, in kDenoiseShare of the budget (all of it
    // once the samples stop); returns the seconds spent, denoising included.
    double renderFrame(double budgetSeconds = kDefaultTracingSeconds);
    // Whether a view shows the denoised image and it is not of the samples and settings as they
    // are now: worth a renderFrame even when nothing accumulates.
    bool denoisePending() const;
    void display() const;               // draws the view(s) into the image area

    // The split view is on: two renders, or the main view's raw and denoised images of one.
    bool comparing() const { return splitsRawAndDenoised() || splitsImageAndView() || comparesTwoRenders(); }
    // Image | view: one render, its image left of the divider and DisplaySettings::view right of it.
    bool splitsImageAndView() const {
        return model_.compare.enabled && model_.compare.sides == CompareSides::ImageAndView;
    }
    bool splitsRawAndDenoised() const {
        return model_.compare.enabled && model_.compare.sides == CompareSides::RawAndDenoised;
    }
    bool comparesTwoRenders() const {
        return model_.compare.enabled && model_.compare.sides == CompareSides::TwoRenders && right_ != nullptr;
    }
    // Whether a side shows the denoised image (where its tracer has one): the main view while
    // ViewerModel::denoise is on, the right half of a raw | denoised split, the right render of
    // two while CompareSettings::rightDenoised is on; never a debug view, which has no noise.
    bool showsDenoised(Side side) const;
    // How a side is displayed: ViewerModel::display with `denoised` as showsDenoised says.
    DisplaySettings displaySettings(Side side) const;
    // The tracer of a side: in a raw | denoised split both sides are the main view's.
    const PathTracer& tracer(Side side) const { return *view(side).tracer; }
    ViewStats stats(Side side) const;
    const RenderSettings& settings(Side side) const;
    glm::ivec2 renderSize() const { return renderSize_; }
    // The size the image area asks for (its size times the resolution scale). The render keeps
    // its own size through a resize or Tab while it holds work worth keeping (see update); until
    // then it is displayed scaled, and R (kRestart) renders at this size.
    glm::ivec2 wantedRenderSize() const;
    PixelRect imageArea() const { return imageArea_; }
    // Where the image is drawn: the largest rectangle of the render's aspect ratio in the image
    // area, centred (the whole area when the render has the area's shape).
    PixelRect displayArea() const;
    int dividerX() const; // framebuffer column of the split view's divider
    // Reload attempts so far (scene, environment map or shaders, successful or not).
    int reloadCount() const { return reloadCount_; }
    // Whether the views still accumulate (not paused, target not reached).
    bool accumulating() const;

    // The paths behind a pixel (x from the left, y from the top of the render), traced on the GPU
    // by the main view's tracer as it renders now (renderer/tracer/PathRecorder.*): its samples 0 ..
    // count - 1. Throws std::invalid_argument for a pixel outside the render or count < 1.
    struct TracedPaths {
        glm::ivec2 pixel{0, 0};
        glm::ivec2 imageSize{0, 0};
        RenderSettings settings;
        CameraDesc camera; // the view they were traced from
        std::vector<RecordedPath> paths;
    };
    const TracedPaths& tracePaths(glm::ivec2 pixel, int count);
    const std::optional<TracedPaths>& tracedPaths() const { return tracedPaths_; }

private:
    struct View {
        std::unique_ptr<PathTracer> tracer;
        TileCost cost;
        TileCost previewCost; // of the preview's rows (PathTracer::renderPreviewRows)
        double renderSeconds = 0.0;
        int seenRestartCount = -1; // the tracer's restartCount() when renderSeconds was zeroed
        int estimatedSamples = 0;  // the sample count `error` (and `trueError`) was estimated at
        double estimatedSeconds = 0.0; // renderSeconds then
        ErrorEstimate error;
        std::vector<std::pair<float, float>> errorHistory;
        std::optional<ErrorMetrics> trueError;
        std::vector<std::pair<float, float>> trueErrorHistory;
        std::chrono::steady_clock::time_point lastEstimate{};
        // Means read back earlier in this accumulation, at sample counts at least doubling, for
        // the error estimate (which compares the mean with one at half the samples or fewer).
        std::vector<std::pair<int, ImageRgbF>> earlierMeans;
        TileCost denoiseCost; // of a row of the denoiser's passes (PathTracer::advanceDenoised)
        std::optional<ErrorMetrics> denoisedTrueError;       // of the denoised image, with a reference
        // While the model's target error is on (the main view only): AdaptiveSampler stops pixels
        // at its checks, which renderFrame runs after the pass that reaches one. Made afresh at
        // every restart (adaptiveRestartCount tells), since a new accumulation starts its checks over.
        std::unique_ptr<AdaptiveSampler> adaptive;
        int adaptiveRestartCount = -1;
        int adaptiveChecks = 0;
    };

    View& view(Side side) { return side == Side::Left || !comparesTwoRenders() ? left_ : *right_; }
    const View& view(Side side) const { return side == Side::Left || !comparesTwoRenders() ? left_ : *right_; }
    bool twoRendersWanted() const {
        return model_.compare.enabled && model_.compare.sides == CompareSides::TwoRenders;
    }
    void syncDenoise();
    void syncAdaptive();
    void syncOtherImages();
    bool denoiseStale(const View& view) const;
    void denoise(View& view, double seconds); // bands of the view's denoise for about `seconds`
    RenderSettings effectiveSettings(const RenderSettings& settings) const;
    bool wantsSamples(const View& view, int passesThisFrame) const;
    void syncView(View& view, const RenderSettings& settings, unsigned changes);
    void trackRestart(View& view);
    void updateErrorEstimate(View& view);
    void followImageArea(unsigned changes);
    void recordErrorEstimate(View& view, const PixelStatistics& statistics);
    void watchFiles();
    void reloadShaders();
    void applyScene(Scene scene, std::shared_ptr<const EnvironmentMap> map);
    bool restoreEdits(const SceneEdits& state);
    void setPatternTarget();
    unsigned restartOnCompare();

    ViewerModel model_;
    std::filesystem::path shaderDir_;
    PathTracerOptions programOptions_;
    View left_;
    std::unique_ptr<View> right_; // created the first time compare mode is turned on
    std::shared_ptr<const OcioView> ocioView_; // on every tracer (PathTracer::setOcioView)
    std::vector<OcioDisplayViews> ocioDisplays_;
    PixelRect imageArea_;
    glm::ivec2 renderSize_{0, 0};
    glm::ivec2 wantedSize_{0, 0};                 // wantedRenderSize() as last seen
    std::chrono::steady_clock::time_point wantedSince_{}; // when it last changed
    float followedScale_ = 1.0f;                  // the resolution scale renderSize_ was set with
    FileWatcher watcher_;
    int reloadCount_ = 0;
    // What update() last saw, to act on a change: a grid or stratified sampler newly chosen gets a
    // target (setPatternTarget), and the split view newly turned on restarts both sides.
    SamplerMode seenSampler_[2] = {SamplerMode::Random, SamplerMode::Random};
    bool seenCompare_ = false;
    float seenTargetError_ = 0.0f; // the target error as update() last applied it; 0: off
    std::string saveTarget_;
    // The open scene came from an image and no file holds it (SceneInput::carriedSceneIsInItsFile
    // false): unsaved until Save writes it or another scene is opened.
    bool carriedSceneUnsaved_ = false;
    std::vector<std::filesystem::path> allowedDirectories_; // --allow-dir and the prompt's answers (ReadScope.h)
    // The pixel inspector's last probe, and what it was probed for.
    struct PixelProbe {
        glm::ivec2 pixel{-1};
        Side side = Side::Left;
        int restartCount = -1;
        CameraDesc camera; // the view the hit was probed with: the pin's
        std::optional<SurfaceHit> hit;
        CameraRayMedia media;
    };
    PixelProbe pixelProbe_;
    std::unique_ptr<PathRecorder> pathRecorder_; // built on the first tracePaths
    std::optional<TracedPaths> tracedPaths_;
    EditHistory history_;
};

} // namespace ptview
