#pragma once
// What the viewer's user controls: the scene with their edits and every render and display
// setting. The panels, the mouse and keyboard and `--script` commands edit this model;
// ViewerSession pushes the changes to the renderer. Nothing here knows about ImGui or OpenGL.

#include <ptview/settings/Backend.h>
#include <ptview/settings/DenoiseSettings.h>
#include <ptview/settings/OcioRequest.h>
#include <ptview/scene/EnvironmentMap.h>
#include <ptview/model/ImageZoom.h>
#include <ptview/io/Image.h>
#include <ptview/settings/RenderSettings.h>
#include <ptview/scene/Scene.h>
#include <ptview/settings/ToneMapper.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace ptview {

// What the split view's two halves show.
enum class CompareSides {
    TwoRenders,     // two renders: the left half with ViewerModel::settings, the right with `right`
    RawAndDenoised, // one render, the main view's: its raw mean left of the divider, denoised right of it
    ImageAndView,   // one render, the main view's: the image left of the divider, DisplaySettings::view right of it
};

struct CompareSettings {
    bool enabled = false;
    CompareSides sides = CompareSides::TwoRenders;
    RenderSettings right;
    // Two renders: whether the right half shows its render denoised (with ViewerModel::denoise's
    // iterations and strength); the left half follows ViewerModel::denoise.enabled.
    bool rightDenoised = false;
    float dividerFraction = 0.5f; // where the divider is, as a fraction of the image width
    // Equal time gives both sides the same GPU time per frame (the fair comparison: a cheaper
    // integrator gets more samples); otherwise both get the same number of samples.
    bool equalTime = true;
};

constexpr int kMaxTracedPaths = 1024; // the Pixel panel's and path-count's bound on ViewerModel::pathCount

struct ViewerModel {
    Scene scene;     // what is rendered, the user's edits included
    Scene fileScene; // as last read from scene.path: the base a reload merges against
    // The decoded map scene.environmentMap names (null for none), kept so that changing its
    // intensity or rotation does not read the file again.
    std::shared_ptr<const EnvironmentMap> environmentMap;

    RenderSettings settings;
    DisplaySettings display; // its `denoised` is ViewerSession's to set per side, from `denoise` and `compare`
    // The denoiser (docs/denoising.md): while enabled the main view shows a filtered copy of its
    // accumulation instead of the raw mean. Biased, and it restarts nothing: the samples go on
    // accumulating raw underneath (ViewerSession::renderFrame says how often it filters them).
    DenoiseSettings denoise;
    Backend backend = Backend::Fragment; // how both views run (compute needs OpenGL 4.3)
    std::string backendChoice;           // how `auto` chose it at start ("" when the user named one)
    float resolutionScale = 1.0f; // render size / image area size
    int maxSamplesPerFrame = 0;   // 0: as many as fit the frame's time budget
    bool paused = false;
    int targetSamples = 0;        // stop accumulating at this many samples per pixel; 0: never
    // Adaptive sampling of the main view (docs/viewer.md, "Target error"): while targetErrorOn,
    // pixels stop as `render --noise-threshold targetError` stops them, and the accumulation stops
    // when the estimated RMS relative error reaches targetError (0.01: 1%) or every pixel stopped.
    // The value is kept while off, so the Render panel's checkbox brings it back.
    bool targetErrorOn = false;
    float targetError = 0.01f;
    CompareSettings compare;
    // The pixel inspector's pixel: one pixel of the full-size render, x from the left and y from
    // the top, as in a saved PNG and every pixel coordinate the user sees (the Pixel panel,
    // `pin-pixel X Y`). Unpinned (reset) whenever the render size changes, since the same numbers
    // would then name another place of the picture. nullopt: none pinned.
    std::optional<glm::ivec2> pinnedPixel;
    // A reference image of the scene (a PFM, e.g. from `ptview render` with many samples): with it
    // the Stats panel shows the true error, not only the estimate. Null for none.
    std::shared_ptr<const ImageRgbF> reference;
    std::filesystem::path referencePath;
    // Another image of the scene (.pfm or .exr, the render's size when loaded) that the difference
    // and other-image views compare the render with; without one they use the reference. Null: none.
    std::shared_ptr<const ImageRgbF> compareImage;
    std::filesystem::path compareImagePath;
    // The image's pixel zoom and pan (ImageZoom.h); DisplaySettings::view says what it shows.
    ImageZoom zoom;
    // How many of the pinned pixel's paths "Trace paths" and `trace-paths` record (ViewerSession::tracePaths).
    int pathCount = 16;

    // What changed since the renderer last saw the model; the editor of a field sets its flag.
    enum Change : unsigned {
        kSceneChanged = 1u,     // geometry, lights or environment: everything is uploaded again
        kMaterialsChanged = 2u, // material parameters only
        kCameraChanged = 4u,
        kRestart = 8u,          // nothing changed, but the user asked to start over
    };
    unsigned pendingChanges = 0;
    // The OpenColorIO view ToneMapper::Ocio shows (ViewerSession::setOcioView; empty config: none),
    // with the display and view named even where the config's defaults chose them.
    OcioRequest ocio;

    // Shown in the UI until the next success of the same kind.
    std::string sceneError;  // the last scene or environment map that could not be read
    std::string shaderError; // the last shader reload that did not compile
    std::string ocioError;   // the last OpenColorIO config, display or view that could not be used
    std::string notice;      // the outcome of the last action (a saved screenshot, a reload)
};

} // namespace ptview
