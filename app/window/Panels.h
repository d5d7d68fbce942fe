#pragma once
// The sections of the viewer's sidebar. Each draws its controls (inside the sidebar window,
// under its own collapsing header drawn by the caller) and edits the session's model or calls
// its actions; the session pushes the changes to the renderer. One file per panel.

#include <ptview/gl/GlObjects.h>
#include <ptview/model/UserPreferences.h>
#include <ptview/window/DetachedWindows.h>
#include <ptview/window/PathsOverlay.h>
#include <ptview/session/UnsavedEditsPrompt.h>
#include <ptview/session/ViewerSession.h>

#include <chrono>
#include <string>
#include <vector>

namespace ptview {

// Text the user is typing and choices that live between frames, one per viewer window.
struct PanelState {
    std::string scenePathInput;       // Scene panel: a path typed by the user
    // Quit, open and Reload waiting for "save your edits?" (drawUnsavedEditsDialog asks).
    UnsavedEditsPrompt unsavedEdits;
    std::string environmentPathInput; // Environment panel: likewise, for an .hdr
    std::string referencePathInput;   // Stats panel: a reference image (.pfm, .exr)
    std::string compareImagePathInput; // Render panel's view controls: the difference views' image
    std::string ocioConfigInput;      // Render panel: an OpenColorIO config.ocio
    std::string screenshotMessage;    // Render panel: where the last screenshot went (or why not)
    bool screenshotFailed = false;
    // The same, briefly on the image (kImageNoticeSeconds), where it is seen with the sidebar
    // hidden or the Render panel closed.
    std::string imageNotice;
    bool imageNoticeFailed = false; // shown in red
    std::chrono::steady_clock::time_point imageNoticeSince{};
    // Shows `text` on the image from now on, in red when `failed`: every notice sets all three.
    void showImageNotice(std::string text, bool failed) {
        imageNotice = std::move(text);
        imageNoticeFailed = failed;
        imageNoticeSince = std::chrono::steady_clock::now();
    }
    // Pixel panel: the material its "open in Materials" button asked for (-1: none); the window
    // hands it to the Materials panel and opens that panel.
    int materialToOpen = -1;
    GlTexture pixelMagnifier; // Pixel panel: the magnified neighbourhood, uploaded each time it is drawn
    PathPick selectedPath; // Pixel panel: the traced path and vertex the table shows (clicking a vertex on the image picks it)
    // Panels to open on the next frame ("all" for every one), asked for by a script.
    std::vector<std::string> panelsToOpen;
    DetachedWindows detached; // sections popped out of the sidebar into their own windows
    // The UI scale and high-contrast theme: the Interface panel, Ctrl +/- and scripts change
    // them; the window applies a change on its next frame and keeps it for the next run.
    UserPreferences preferences;
    float uiScaleDragged = 0.0f; // the Interface panel's slider value while it is dragged (0: not dragged)
};

// Undo and Redo, each naming its step ("Undo: roughness of 'floor'"), and how many there are.
void drawEditPanel(ViewerSession& session, PanelState& state);
// What Undo and Redo, Ctrl+Z and Ctrl+Shift+Z (Ctrl+Y) and the script's undo and redo do: the
// session's undo or redo, its outcome ("undid roughness of 'floor'", "nothing to undo") shown on
// the image. False when there was nothing to do or it failed.
bool undoEdit(ViewerSession& session, PanelState& state);
bool redoEdit(ViewerSession& session, PanelState& state);
// Integrator, depth, sampler, samples per frame, pause, target spp, resolution scale, exposure,
// tone mapper, compare mode, screenshot button.
void drawRenderPanel(ViewerSession& session, PanelState& state);
// In the Render panel: the view (image, error map, estimated error, difference, ...), the colour
// map's range, the comparison image, and the pixel zoom (ViewControls.cpp).
void drawViewControls(ViewerSession& session, PanelState& state);
// Open a scene from assets/scenes/ or a typed path; reload; load errors.
void drawScenePanel(ViewerSession& session, PanelState& state);
// Environment map from assets/ or a typed path, intensity, rotation, constant colour.
void drawEnvironmentPanel(ViewerSession& session, PanelState& state);
// Point and spot lights: intensity, colour, position, direction and cone; area lights listed
// with their emission (edited in Materials).
void drawLightsPanel(ViewerSession& session);
// Field of view, eye, orbit target, aperture and focus distance (Ctrl+click sets it), reset.
void drawCameraPanel(ViewerSession& session);
// Samples per pixel, ms per frame, samples per second, elapsed time, error estimate and its plot,
// for each view of a comparison; and, with a reference image loaded, the true error and its plot.
void drawStatsPanel(ViewerSession& session, PanelState& state, double frameSeconds);
// The pixel inspector: the pinned pixel's radiance (linear and displayed), spp, standard error,
// NaN/Inf status, its first hit (position, shape, material with a button to open it, normals,
// distance), the split view's side, and a magnifier; read again each time it is drawn.
void drawPixelPanel(ViewerSession& session, PanelState& state);
// Mouse and keyboard shortcuts.
void drawHelpPanel();
// The UI scale and the high-contrast theme (UserPreferences.h), kept between runs.
void drawInterfacePanel(PanelState& state);
// In the Pixel panel: how many paths to trace for `pixel`, "Trace paths", and the traced paths'
// vertex table (PathsPanel.cpp). `cameraMoved` (PixelInspection::cameraMoved): the pixel now sees
// another place than the pin, so tracing is offered only after a re-pin.
void drawPathsSection(ViewerSession& session, PanelState& state, glm::ivec2 pixel, bool cameraMoved);
// The pinned pixel's traced paths and the selected one's vertex table: in the Pixel panel, or in
// its own window (ownWindow, popped out: the table then shows every column without scrolling sideways).
void drawTracedPathsTable(ViewerSession& session, PanelState& state, bool ownWindow);
// The Render panel's debug view, NaN highlight and light-path explorer controls (also in their own window).
void drawLightPathControls(ViewerModel& model);
// The Render panel's split-view controls (also in their own window).
void drawCompareControls(ViewerModel& model);
// The modal "Unsaved edits" question while state.unsavedEdits has an action waiting: Save,
// Discard, Cancel. Drawn outside the sidebar, so it shows with the sidebar hidden too.
void drawUnsavedEditsDialog(ViewerSession& session, PanelState& state);

// Saves the screenshots (button and F12) and records the outcome in state.
void saveScreenshots(ViewerSession& session, PanelState& state);

// Where the viewer finds the scenes and maps it offers in its lists.
inline const char* assetsDirectory() { return PTVIEW_ASSETS_DIR; }

} // namespace ptview
