#include <ptview/window/Viewer.h>

#include <ptview/window/AllowFolderPrompt.h>
#include <ptview/window/ErrorLegend.h>
#include <ptview/model/CameraController.h>
#include <ptview/io/ImageIO.h>
#include <ptview/window/MaterialsPanel.h>
#include <ptview/commands/OcioOption.h>
#include <ptview/commands/OutputPath.h>
#include <ptview/window/PanelText.h>
#include <ptview/window/PanelWidgets.h>
#include <ptview/window/Panels.h>
#include <ptview/window/PathsOverlay.h>
#include <ptview/io/PrintableText.h>
#include <ptview/gl/Readback.h>
#include <ptview/commands/SceneFromImage.h>
#include <ptview/model/SceneInput.h>
#include <ptview/window/ScriptRunner.h>
#include <ptview/session/ViewerSession.h>
#include <ptview/window/WarpVisualizer.h>
#include <ptview/model/UserPreferences.h>

#include <glad/gl.h>
// GLFW after glad, so it does not pull in the system GL header.
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ptview {
namespace {

using Clock = std::chrono::steady_clock;

constexpr float kSidebarWidth = 380.0f;        // at content scale 1
constexpr float kDividerGrabPixels = 6.0f;     // how close to the divider a drag grabs it
constexpr float kFastFlyFactor = 4.0f;         // with Shift held
// A displayed frame takes about this long: path tracing gets what the display pass, the UI and
// the buffer swap leave of it, so the window stays responsive even on a software rasterizer.
constexpr double kFrameSeconds = 0.033;
constexpr double kMinTracingSeconds = 0.004;
constexpr std::chrono::milliseconds kTitleInterval{250}; // how soon the title's star follows an edit
// Wheel notches closer together than this are one zoom, and so one undo step.
constexpr std::chrono::milliseconds kWheelBurst{500};

// A key press as the key callback saw it: the key, the modifiers held, and the letter it types in
// the keyboard's layout (0 for none), so that Ctrl+Z is the key labelled Z on a QWERTZ or AZERTY
// keyboard too, not the one where a US keyboard has it.
struct KeyPress {
    int key = GLFW_KEY_UNKNOWN;
    int mods = 0;
    char letter = 0;

    bool is(char wanted, int wantedMods) const {
        const bool sameLetter = letter ? letter == wanted : key == GLFW_KEY_A + (wanted - 'a');
        return sameLetter && (mods & (GLFW_MOD_CONTROL | GLFW_MOD_SHIFT | GLFW_MOD_ALT)) == wantedMods;
    }
};

// What the window's callbacks saw since the last frame. Keys that trigger an action are queued
// from the key callback (with the modifiers held then: a fast Ctrl+= is released before the frame
// reads ImGui's), so a press shorter than a (slow) frame is never lost.

struct InputEvents {
    std::vector<KeyPress> pressedKeys;
    double scrollSteps = 0.0; // of the wheel turned over the image area only
    double zoomSteps = 0.0;   // the same with Ctrl held: the image's pixel zoom, not the camera's
    Clock::time_point lastScroll{}; // when the wheel last turned over the image area
    // The image area in window coordinates (top-left origin), as the last layout placed it: a
    // wheel turned anywhere else (over the sidebar) is the sidebar's, and never zooms.
    glm::dvec2 imageTopLeft{0.0};
    glm::dvec2 imageBottomRight{0.0};
    float contentScale = 1.0f;
    bool contentScaleChanged = false;
};

InputEvents& events(GLFWwindow* window) {
    return *static_cast<InputEvents*>(glfwGetWindowUserPointer(window));
}

// Installed before ImGui's own callbacks, which chain to them.
void onKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
    if (action != GLFW_PRESS) return;
    const char* name = glfwGetKeyName(key, scancode); // the layout's, for printable keys
    const char letter = name && name[0] >= 'a' && name[0] <= 'z' && name[1] == '\0' ? name[0] : 0;
    events(window).pressedKeys.push_back(KeyPress{key, mods, letter});
}

// Judged by where the pointer is when the wheel turns, not by ImGui's WantCaptureMouse alone:
// that flag is of the last frame, so a pointer that reached the sidebar and a wheel turned within
// one frame would zoom the camera and restart the accumulation.
void onScroll(GLFWwindow* window, double /*x*/, double y) {
    InputEvents& input = events(window);
    glm::dvec2 cursor;
    glfwGetCursorPos(window, &cursor.x, &cursor.y);
    bool overImage = glm::all(glm::greaterThanEqual(cursor, input.imageTopLeft)) && glm::all(glm::lessThan(cursor, input.imageBottomRight));
    if (overImage) {
        bool control = glfwGetKey(window, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS || glfwGetKey(window, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
        (control ? input.zoomSteps : input.scrollSteps) += y;
        input.lastScroll = Clock::now();
    }
}

void onContentScale(GLFWwindow* window, float xScale, float /*yScale*/) {
    events(window).contentScale = xScale;
    events(window).contentScaleChanged = true;
}

void reportGlfwError(int code, const char* description) {
    std::fprintf(stderr, "ptview: GLFW error %d: %s\n", code, description);
}

// Window coordinates kept free around the window for a window manager's title bar and borders.
constexpr int kDecorationAllowance = 48;

// The scene's aspect ratio, an image of at least 768 rows (small scene resolutions would give an
// image too small to look at, and a sidebar too short for its panels), then shrunk until sidebar
// and image fit the monitor's work area (the screen less task bars), so nothing opens off-screen.
glm::ivec2 initialWindowSize(glm::ivec2 resolution, float sidebarWidth, glm::ivec2 workArea) {
    glm::vec2 image(resolution);
    if (image.y < 768.0f) image *= 768.0f / image.y;
    glm::vec2 room = glm::vec2(workArea - glm::ivec2(0, kDecorationAllowance)) - glm::vec2(sidebarWidth, 0.0f);
    if (room.x > 0.0f && room.y > 0.0f) image *= std::min(1.0f, std::min(room.x / image.x, room.y / image.y));
    glm::ivec2 size(static_cast<int>(image.x + sidebarWidth), static_cast<int>(image.y));
    return glm::max(size, glm::ivec2(1));
}

ImageRgba8 readWindow(glm::ivec2 size) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    ImageRgba8 image = readColorRgba8(size);
    for (size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255; // the window is opaque
    return image;
}

// "ptview — cornell.json *": the scene's file, starred while it has unsaved edits, and saying so
// while the last scene or shader file did not apply (PanelText.h).
std::string titleOf(const ViewerSession& session) {
    const ViewerModel& model = session.model();
    return windowTitle(model.fileScene.path, session.hasUnsavedEdits(), model.sceneError, model.shaderError);
}

// Fonts and widget sizes follow the monitor's content scale (HiDPI) times the user's UI scale;
// the high-contrast theme is for projectors and bright rooms: black panels, white text, a border
// on every field and strong accents (docs/viewer.md, "Interface").
void applyInterfaceStyle(float scale, bool highContrast) {
    ImGuiStyle style;
    ImGui::StyleColorsDark(&style);
    // Slider handles: narrow and translucent, so the value printed over them stays readable.
    style.GrabMinSize = 4.0f;
    style.Colors[ImGuiCol_SliderGrab].w = 0.45f;
    style.Colors[ImGuiCol_SliderGrabActive].w = 0.6f;
    if (highContrast) {
        const ImVec4 black(0.0f, 0.0f, 0.0f, 1.0f), white(1.0f, 1.0f, 1.0f, 1.0f), yellow(1.0f, 0.85f, 0.0f, 1.0f);
        const ImVec4 blue(0.0f, 0.3f, 0.85f, 1.0f), brightBlue(0.15f, 0.5f, 1.0f, 1.0f);
        style.Colors[ImGuiCol_WindowBg] = black;
        style.Colors[ImGuiCol_PopupBg] = black;
        style.Colors[ImGuiCol_Text] = white;
        style.Colors[ImGuiCol_TextDisabled] = ImVec4(0.85f, 0.85f, 0.85f, 1.0f);
        style.Colors[ImGuiCol_Border] = white;
        style.Colors[ImGuiCol_FrameBg] = ImVec4(0.12f, 0.12f, 0.12f, 1.0f);
        style.Colors[ImGuiCol_FrameBgHovered] = ImVec4(0.25f, 0.25f, 0.25f, 1.0f);
        style.Colors[ImGuiCol_FrameBgActive] = ImVec4(0.35f, 0.35f, 0.35f, 1.0f);
        for (ImGuiCol col : {ImGuiCol_Header, ImGuiCol_Button, ImGuiCol_TitleBgActive}) style.Colors[col] = blue;
        for (ImGuiCol col : {ImGuiCol_HeaderHovered, ImGuiCol_ButtonHovered, ImGuiCol_HeaderActive, ImGuiCol_ButtonActive})
            style.Colors[col] = brightBlue;
        for (ImGuiCol col : {ImGuiCol_CheckMark, ImGuiCol_SliderGrab, ImGuiCol_SliderGrabActive, ImGuiCol_PlotLines,
                             ImGuiCol_PlotHistogram, ImGuiCol_NavHighlight})
            style.Colors[col] = yellow;
        style.FrameBorderSize = 1.0f;
        style.WindowBorderSize = 2.0f;
        style.GrabMinSize = 8.0f;
    }
    style.ScaleAllSizes(scale);
    ImGui::GetStyle() = style;
    ImGui::GetIO().FontGlobalScale = scale;
}

// The window: a sidebar of panels on the left, the image on the right (all of it with the
// sidebar hidden), the mouse and keyboard driving the camera over the image.
class ViewerWindow {
public:
    ViewerWindow(GLFWwindow* window, ViewerSession& session, const ViewerOptions& options)
        : window_(window), session_(session), options_(options), warpVisualizer_(options.warp) {
        warpVisualizer_.setActive(options.showWarp);
        if (preferencesPath_) {
            std::string warning;
            panelState_.preferences = savedPreferences_ = loadPreferences(*preferencesPath_, warning);
            if (!warning.empty()) printMessage("warning: " + warning);
        }
    }

    int run(std::optional<ScriptRunner>& script);

private:
    bool waitForEvents(bool busy);
    void applyInterface();
    void keepPreferences();
    double timeFrame();
    void updateSession();
    void drawImage();
    bool frameScreenshotDone(int frame, Clock::time_point start);
    void handleKeys();
    void handleControlKey(int key);
    void scaleInterface(float factor);
    void answerUnsavedEdits(const std::vector<KeyPress>& keys);
    bool editInProgress() const;
    void updateTitle();
    void handleMouseAndFlight(double seconds);
    std::optional<glm::vec2> imageFractionAtCursor(glm::dvec2 cursor) const;
    glm::vec2 framebufferAt(glm::dvec2 cursor) const;
    void drawLegend();
    void focusAtCursor(glm::dvec2 cursor);
    void pinAtCursor(glm::dvec2 cursor);
    void drawPinnedPixelMarker();
    ScreenRect imageOnScreen() const;
    bool pinnedPathsShown() const;
    void drawTracedPaths();
    void pickPathVertexAtCursor(glm::dvec2 cursor);
    void layout();
    void drawUi();
    void drawSidebar();
    void drawDetachedWindows();
    void drawCompareLabels();
    void drawImageNotes();
    void drawImageNote(const std::string& text, ImVec2 anchor, bool alignRight, bool alignBottom, ImU32 colour);

    GLFWwindow* window_;
    ViewerSession& session_;
    const ViewerOptions& options_;
    WarpVisualizer warpVisualizer_;
    MaterialsPanel materialsPanel_;
    PanelState panelState_;
    bool sidebarVisible_ = true;
    bool helpOpen_ = false;
    float sidebarWidth_ = kSidebarWidth; // in window coordinates, as ImGui measures
    std::optional<std::filesystem::path> preferencesPath_ = defaultPreferencesPath();
    std::optional<UserPreferences> appliedPreferences_; // what the style shows; none before the first frame
    UserPreferences savedPreferences_;                  // what the preferences file holds
    glm::ivec2 framebufferSize_{0, 0};
    glm::vec2 framebufferScale_{1.0f}; // framebuffer pixels per window coordinate
    glm::dvec2 lastCursor_{0.0};
    bool draggingDivider_ = false;
    double frameSeconds_ = 0.0;    // smoothed time between displayed frames
    double overheadSeconds_ = 0.0; // smoothed part of a frame that is not path tracing
    double lastTracingSeconds_ = 0.0;
    Clock::time_point lastFrame_{};
    std::string title_;
    Clock::time_point lastTitleUpdate_{};
};

void ViewerWindow::handleKeys() {
    std::vector<KeyPress> keys;
    std::swap(keys, events(window_).pressedKeys);
    if (panelState_.unsavedEdits.pending()) return answerUnsavedEdits(keys);
    if (ImGui::GetIO().WantCaptureKeyboard) return; // typing into a field (which has its own Ctrl+Z)
    ViewerModel& model = session_.model();
    for (const KeyPress& press : keys) {
        if (panelState_.unsavedEdits.pending()) break; // keys typed after Esc are no answer to an unseen question
        if (press.is('z', GLFW_MOD_CONTROL)) {
            undoEdit(session_, panelState_);
            continue;
        }
        if (press.is('z', GLFW_MOD_CONTROL | GLFW_MOD_SHIFT) || press.is('y', GLFW_MOD_CONTROL)) {
            redoEdit(session_, panelState_);
            continue;
        }
        if (press.mods & GLFW_MOD_CONTROL) {
            handleControlKey(press.key);
            continue;
        }
        switch (press.key) {
        case GLFW_KEY_ESCAPE: panelState_.unsavedEdits.request(session_, UnsavedEditsPrompt::Action::Quit); break;
        case GLFW_KEY_F12: saveScreenshots(session_, panelState_); break;
        case GLFW_KEY_F1: helpOpen_ = !helpOpen_; break;
        case GLFW_KEY_TAB: sidebarVisible_ = !sidebarVisible_; break;
        case GLFW_KEY_SPACE: model.paused = !model.paused; break;
        case GLFW_KEY_R: model.pendingChanges |= ViewerModel::kRestart; break;
        case GLFW_KEY_C: model.compare.enabled = !model.compare.enabled; break;
        case GLFW_KEY_N: model.denoise.enabled = !model.denoise.enabled; break; // D flies right (W A S D)
        case GLFW_KEY_F: session_.resetCamera(); break;
        case GLFW_KEY_V: { // the next view: image, error map, estimated error, difference, ...
            const auto& views = displayViewNames();
            auto at = std::find_if(views.begin(), views.end(), [&](const auto& e) { return e.value == model.display.view; });
            model.display.view = (at == views.end() || std::next(at) == views.end()) ? views.front().value : std::next(at)->value;
            break;
        }
        case GLFW_KEY_0: session_.fitImage(); break;
        case GLFW_KEY_1: session_.zoomImageTo(1.0f); break;
        case GLFW_KEY_EQUAL: case GLFW_KEY_KP_ADD: session_.zoomImageBySteps(1); break;
        case GLFW_KEY_MINUS: case GLFW_KEY_KP_SUBTRACT: session_.zoomImageBySteps(-1); break;
        default: break;
        }
    }
}

// Ctrl + (with or without Shift) and Ctrl - scale the interface; Ctrl 0 sets it back to 1.
void ViewerWindow::handleControlKey(int key) {
    switch (key) {
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_KP_ADD: scaleInterface(kUiScaleStep); break;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT: scaleInterface(1.0f / kUiScaleStep); break;
    case GLFW_KEY_0:
    case GLFW_KEY_KP_0: scaleInterface(1.0f / panelState_.preferences.uiScale); break;
    default: break;
    }
}

// Past either end of kUiScale the scale stops there, and the image says so.
void ViewerWindow::scaleInterface(float factor) {
    std::string message;
    panelState_.preferences.uiScale = clampedUiScale(panelState_.preferences.uiScale * factor, &message);
    if (std::abs(panelState_.preferences.uiScale - 1.0f) < 1e-4f) panelState_.preferences.uiScale = 1.0f; // back to exactly 1
    if (!message.empty()) panelState_.showImageNotice(message, false);
}

// While the "Unsaved edits" question is open, the keys answer it (the dialog has buttons too).
void ViewerWindow::answerUnsavedEdits(const std::vector<KeyPress>& keys) {
    for (const KeyPress& press : keys) {
        if (!panelState_.unsavedEdits.pending()) break;
        const int key = press.key;
        if (key == GLFW_KEY_ESCAPE) panelState_.unsavedEdits.answer(session_, UnsavedEditsPrompt::Answer::Cancel);
        if (key == GLFW_KEY_S) panelState_.unsavedEdits.answer(session_, UnsavedEditsPrompt::Answer::Save);
        if (key == GLFW_KEY_D) panelState_.unsavedEdits.answer(session_, UnsavedEditsPrompt::Answer::Discard);
    }
}

// Whether an edit is still going on, to be one undo step when it ends (ViewerSession::recordEdits):
// a widget held (a slider or drag being dragged, a field being typed into), a mouse button down
// (a drag over the image, a click not yet released), the wheel turned within a burst, a fly key held.
bool ViewerWindow::editInProgress() const {
    if (ImGui::IsAnyItemActive()) return true;
    for (int button : {GLFW_MOUSE_BUTTON_LEFT, GLFW_MOUSE_BUTTON_RIGHT, GLFW_MOUSE_BUTTON_MIDDLE})
        if (glfwGetMouseButton(window_, button) == GLFW_PRESS) return true;
    if (Clock::now() - events(window_).lastScroll < kWheelBurst) return true;
    for (int key : {GLFW_KEY_W, GLFW_KEY_A, GLFW_KEY_S, GLFW_KEY_D, GLFW_KEY_Q, GLFW_KEY_E})
        if (glfwGetKey(window_, key) == GLFW_PRESS) return true;
    return false;
}

// A few times a second: comparing the scene with its file serializes both, too much for every
// frame (docs/performance.md, "Measurements behind code comments").
void ViewerWindow::updateTitle() {
    Clock::time_point now = Clock::now();
    if (now - lastTitleUpdate_ < kTitleInterval) return;
    lastTitleUpdate_ = now;
    std::string title = titleOf(session_);
    if (title == title_) return;
    glfwSetWindowTitle(window_, printableText(title).c_str()); // the scene's name may be a stranger's
    title_ = std::move(title);
}

void ViewerWindow::handleMouseAndFlight(double seconds) {
    const ImGuiIO& io = ImGui::GetIO();
    ViewerModel& model = session_.model();
    CameraDesc camera = model.scene.camera;

    glm::dvec2 cursor;
    glfwGetCursorPos(window_, &cursor.x, &cursor.y);
    glm::dvec2 delta = cursor - lastCursor_;
    lastCursor_ = cursor;
    double scroll = events(window_).scrollSteps;
    events(window_).scrollSteps = 0.0;
    double zoomSteps = events(window_).zoomSteps;
    events(window_).zoomSteps = 0.0;

    bool left = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    bool right = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
                 glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
    bool shift = glfwGetKey(window_, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                 glfwGetKey(window_, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
    bool control = glfwGetKey(window_, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS ||
                   glfwGetKey(window_, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
    bool alt = glfwGetKey(window_, GLFW_KEY_LEFT_ALT) == GLFW_PRESS || glfwGetKey(window_, GLFW_KEY_RIGHT_ALT) == GLFW_PRESS;
    // The divider, in window coordinates.
    float dividerX = static_cast<float>(session_.dividerX()) / framebufferScale_.x;
    if (!left) draggingDivider_ = false;
    if (!io.WantCaptureMouse) {
        if (left && !draggingDivider_ && session_.comparing() && std::abs(cursor.x - delta.x - dividerX) < kDividerGrabPixels &&
            ImGui::IsMouseClicked(ImGuiMouseButton_Left))
            draggingDivider_ = true;
        PixelRect area = session_.viewArea(); // the divider is a fraction of it
        float imageHeight = std::max(1.0f, static_cast<float>(area.size.y) / framebufferScale_.y);
        // ImGui sees a click even when press and release fell within one frame; GLFW's state may not.
        bool clicked = ImGui::IsMouseClicked(ImGuiMouseButton_Left);
        // A plain click on a traced path's vertex selects it for the Pixel panel's table (a drag
        // from there still orbits).
        if (clicked && !control && !alt && !shift) pickPathVertexAtCursor(cursor);
        if (control && (left || clicked)) {
            // Ctrl+click focuses; a Ctrl+drag neither orbits nor pans.
            if (clicked) focusAtCursor(cursor);
            camera = model.scene.camera;
        } else if (control && right) {
            // Ctrl+right or middle drag pans the image (its pixel zoom), not the camera.
            if (delta != glm::dvec2(0.0))
                session_.panImage(glm::vec2(static_cast<float>(delta.x) * framebufferScale_.x,
                                            static_cast<float>(-delta.y) * framebufferScale_.y));
        } else if (alt && (left || clicked)) {
            // Alt+click pins the pixel (or unpins it); an Alt+drag neither orbits nor pans.
            if (clicked) pinAtCursor(cursor);
        } else if (draggingDivider_) {
            float areaLeft = static_cast<float>(area.origin.x) / framebufferScale_.x;
            float areaWidth = std::max(1.0f, static_cast<float>(area.size.x) / framebufferScale_.x);
            model.compare.dividerFraction = std::clamp((static_cast<float>(cursor.x) - areaLeft) / areaWidth, 0.0f, 1.0f);
        } else if (delta != glm::dvec2(0.0) && (right || (left && shift))) {
            camera = panCamera(camera, static_cast<float>(-delta.x) / imageHeight, static_cast<float>(delta.y) / imageHeight);
        } else if (delta != glm::dvec2(0.0) && left) {
            camera = orbitCamera(camera, static_cast<float>(-delta.x) * kOrbitDegreesPerPixel,
                                 static_cast<float>(delta.y) * kOrbitDegreesPerPixel);
        }
        if (scroll != 0.0) camera = zoomCamera(camera, zoomFactorForWheel(static_cast<float>(scroll)));
        // Ctrl+wheel: the image's pixel zoom, a power of two a notch, about the pointer.
        if (zoomSteps != 0.0)
            session_.zoomImageBySteps(zoomSteps > 0.0 ? std::max(1, static_cast<int>(std::lround(zoomSteps)))
                                                      : std::min(-1, static_cast<int>(std::lround(zoomSteps))),
                                      framebufferAt(cursor));
    }
    if (!io.WantCaptureKeyboard) {
        glm::vec3 move(0.0f);
        auto held = [&](int key) { return glfwGetKey(window_, key) == GLFW_PRESS ? 1.0f : 0.0f; };
        move.z = held(GLFW_KEY_W) - held(GLFW_KEY_S);
        move.x = held(GLFW_KEY_D) - held(GLFW_KEY_A);
        move.y = held(GLFW_KEY_E) - held(GLFW_KEY_Q);
        if (move != glm::vec3(0.0f)) {
            // A slow frame must not fling the camera: cap the step at a tenth of a second.
            float step = flyDistance(camera, static_cast<float>(std::min(seconds, 0.1))) * (shift ? kFastFlyFactor : 1.0f);
            camera = flyCamera(camera, move, step);
        }
    }
    const CameraDesc& before = model.scene.camera;
    camera = usableCamera(camera, before); // a move past the scene's bounds stops at the edge
    if (camera.eye != before.eye || camera.target != before.target) {
        model.scene.camera = camera;
        model.pendingChanges |= ViewerModel::kCameraChanged;
    }
}

// Where the cursor (window coordinates from the top-left) is on the image, as fractions of it
// from its top-left corner; nullopt off the image. Click-to-focus and the pixel inspector share it.
std::optional<glm::vec2> ViewerWindow::imageFractionAtCursor(glm::dvec2 cursor) const {
    PixelRect area = session_.imageRect(); // zoomed and panned
    if (area.size.x <= 0 || area.size.y <= 0) return std::nullopt;
    glm::vec2 pixel = framebufferAt(cursor);
    PixelRect view = session_.viewArea();
    if (pixel.x < static_cast<float>(view.origin.x) || pixel.y < static_cast<float>(view.origin.y) ||
        pixel.x > static_cast<float>(view.origin.x + view.size.x) || pixel.y > static_cast<float>(view.origin.y + view.size.y))
        return std::nullopt; // outside the part of the window the image is drawn in
    glm::vec2 fromBottomLeft = (pixel - glm::vec2(area.origin)) / glm::vec2(area.size);
    if (glm::any(glm::lessThan(fromBottomLeft, glm::vec2(0.0f))) || glm::any(glm::greaterThan(fromBottomLeft, glm::vec2(1.0f))))
        return std::nullopt;
    return glm::vec2(fromBottomLeft.x, 1.0f - fromBottomLeft.y);
}

// A cursor position (window coordinates from the top-left) in framebuffer pixels, as OpenGL
// counts them (from the bottom-left).
glm::vec2 ViewerWindow::framebufferAt(glm::dvec2 cursor) const {
    glm::vec2 pixel = glm::vec2(cursor) * framebufferScale_;
    pixel.y = static_cast<float>(framebufferSize_.y) - pixel.y;
    return pixel;
}

// Click-to-focus on the surface under the cursor, when it is on the image.
void ViewerWindow::focusAtCursor(glm::dvec2 cursor) {
    if (std::optional<glm::vec2> fraction = imageFractionAtCursor(cursor)) session_.focusAt(*fraction);
}

// Alt+click: pins the render pixel under the cursor (the resolution scale and a render shown
// scaled included), or unpins it; the Pixel panel opens to show it.
void ViewerWindow::pinAtCursor(glm::dvec2 cursor) {
    // Through the zoom: the render pixel drawn under the cursor, exactly.
    std::optional<glm::ivec2> pixel = session_.pixelAtFramebuffer(framebufferAt(cursor));
    if (!pixel) return;
    session_.togglePinnedPixel(*pixel);
    if (session_.model().pinnedPixel) panelState_.panelsToOpen.push_back("pixel");
}

// A square around the pinned pixel (at least a few points wide, the pixel's own size when the
// image is zoomed in) and a crosshair beside it, over the image.
void ViewerWindow::drawPinnedPixelMarker() {
    const std::optional<glm::ivec2>& pinned = session_.model().pinnedPixel;
    glm::ivec2 render = session_.renderSize();
    if (!pinned || render.x <= 0 || render.y <= 0) return;
    PixelRect area = session_.imageRect();
    glm::vec2 cell = glm::vec2(area.size) / glm::vec2(render) / framebufferScale_; // one pixel, in window coordinates
    // The pixel's top-left corner: the area's origin is its bottom-left corner, in framebuffer pixels.
    glm::vec2 topLeft(static_cast<float>(area.origin.x) / framebufferScale_.x + cell.x * static_cast<float>(pinned->x),
                      static_cast<float>(framebufferSize_.y - area.origin.y - area.size.y) / framebufferScale_.y +
                          cell.y * static_cast<float>(pinned->y));
    glm::vec2 centre = topLeft + 0.5f * cell;
    // Zoomed in, the pin may lie outside the window's part that shows the image: no mark over the sidebar.
    if (std::optional<glm::ivec2> shown = session_.pixelAtFramebuffer(framebufferAt(glm::dvec2(centre))); shown != pinned) return;
    glm::vec2 half = glm::max(0.5f * cell, glm::vec2(3.0f)) + 1.0f;
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    const ImU32 dark = IM_COL32(0, 0, 0, 200), bright = IM_COL32(255, 64, 255, 255);
    for (int pass = 0; pass < 2; ++pass) { // a dark outline under the bright mark, so it shows on any colour
        float thickness = pass == 0 ? 3.0f : 1.0f;
        ImU32 colour = pass == 0 ? dark : bright;
        draw->AddRect(ImVec2(centre.x - half.x, centre.y - half.y), ImVec2(centre.x + half.x, centre.y + half.y), colour, 0.0f, 0,
                      thickness);
        float gap = half.x + 3.0f, reach = half.x + 10.0f;
        draw->AddLine(ImVec2(centre.x - reach, centre.y), ImVec2(centre.x - gap, centre.y), colour, thickness);
        draw->AddLine(ImVec2(centre.x + gap, centre.y), ImVec2(centre.x + reach, centre.y), colour, thickness);
        draw->AddLine(ImVec2(centre.x, centre.y - reach), ImVec2(centre.x, centre.y - gap), colour, thickness);
        draw->AddLine(ImVec2(centre.x, centre.y + gap), ImVec2(centre.x, centre.y + reach), colour, thickness);
    }
}

// The render on screen, in window coordinates from the top-left (ImGui's): the display area's
// origin is its bottom-left corner, in framebuffer pixels.
ScreenRect ViewerWindow::imageOnScreen() const {
    PixelRect area = session_.imageRect();
    return ScreenRect{{static_cast<float>(area.origin.x) / framebufferScale_.x,
                       static_cast<float>(framebufferSize_.y - area.origin.y - area.size.y) / framebufferScale_.y},
                      glm::vec2(area.size) / framebufferScale_};
}

// The traced paths belong to the pinned pixel of this render size; another pin hides them.
bool ViewerWindow::pinnedPathsShown() const {
    const std::optional<ViewerSession::TracedPaths>& traced = session_.tracedPaths();
    const std::optional<glm::ivec2>& pinned = session_.model().pinnedPixel;
    return traced && pinned && *pinned == traced->pixel && traced->imageSize == session_.renderSize();
}

// Over the image, under the panels; projected with the camera as it is now, so orbiting shows
// them from the side while the image re-renders from there.
void ViewerWindow::drawTracedPaths() {
    if (!pinnedPathsShown()) return;
    drawPathsOverlay(*ImGui::GetBackgroundDrawList(), *session_.tracedPaths(), session_.model().scene.camera,
                     session_.renderSize(), imageOnScreen(), panelState_.selectedPath,
                     session_.tracer(ViewerSession::Side::Left).gpuScene().sceneRadius());
}

void ViewerWindow::pickPathVertexAtCursor(glm::dvec2 cursor) {
    if (!pinnedPathsShown()) return;
    if (std::optional<PathPick> pick = pickPathVertex(*session_.tracedPaths(), session_.model().scene.camera,
                                                      session_.renderSize(), imageOnScreen(), glm::vec2(cursor))) {
        panelState_.selectedPath = *pick;
        panelState_.panelsToOpen.push_back("pixel");
    }
}

void ViewerWindow::layout() {
    glm::ivec2 windowSize;
    glfwGetWindowSize(window_, &windowSize.x, &windowSize.y);
    framebufferScale_ = glm::vec2(framebufferSize_) / glm::max(glm::vec2(windowSize), glm::vec2(1.0f));
    int sidebarPixels = sidebarVisible_ ? static_cast<int>(sidebarWidth_ * framebufferScale_.x) : 0;
    sidebarPixels = std::min(sidebarPixels, framebufferSize_.x - 1); // keep a column of image
    session_.setImageArea(PixelRect{{sidebarPixels, 0}, {framebufferSize_.x - sidebarPixels, framebufferSize_.y}});
    // The same area for the scroll callback, which runs between frames.
    events(window_).imageTopLeft = glm::dvec2(static_cast<double>(sidebarPixels) / framebufferScale_.x, 0.0);
    events(window_).imageBottomRight = glm::dvec2(windowSize);
}

void ViewerWindow::drawSidebar() {
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(sidebarWidth_, io.DisplaySize.y), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(200.0f, io.DisplaySize.y), ImVec2(io.DisplaySize.x * 0.8f, io.DisplaySize.y));
    ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoTitleBar;
    if (ImGui::Begin("ptview", nullptr, flags)) {
        ViewerModel& model = session_.model();
        ImGui::TextUnformatted(printableText(model.scene.path.filename().string()).c_str());
        ImGui::SameLine();
        ImGui::TextDisabled("(F1: help, Tab: hide)");
        // Room for the longest label beside a widget ("samples/frame") and no more, so that combo
        // boxes show whole entries ("Full (global illumination)" was cut with a fixed 150-pixel
        // label column).
        float labelWidth = ImGui::CalcTextSize("samples/frame").x + 2.0f * ImGui::GetStyle().ItemInnerSpacing.x;
        ImGui::PushItemWidth(-labelWidth);
        std::vector<std::string> toOpen;
        std::swap(toOpen, panelState_.panelsToOpen);
        // A header, opened when a script asked for it.
        auto header = [&](const char* label, ImGuiTreeNodeFlags flags = 0) {
            std::string name = label;
            std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
            if (std::find(toOpen.begin(), toOpen.end(), name) != toOpen.end() ||
                std::find(toOpen.begin(), toOpen.end(), "all") != toOpen.end())
                ImGui::SetNextItemOpen(true);
            return ImGui::CollapsingHeader(label, flags);
        };
        // The warp visualizer replaces the render: the panels about it (samples, samples/s,
        // its settings and scene) would describe a picture that is not on the screen.
        bool rendering = !warpVisualizer_.active();
        if (!rendering) noteText("The path tracer pauses while the warp visualizer is shown.");
        if (rendering && header("Edit", ImGuiTreeNodeFlags_DefaultOpen)) drawEditPanel(session_, panelState_);
        if (rendering && header("Render", ImGuiTreeNodeFlags_DefaultOpen)) drawRenderPanel(session_, panelState_);
        if (rendering && header("Stats", ImGuiTreeNodeFlags_DefaultOpen)) drawStatsPanel(session_, panelState_, frameSeconds_);
        bool pixelAsked = std::find(toOpen.begin(), toOpen.end(), "pixel") != toOpen.end();
        if (rendering && header("Pixel")) {
            if (pixelAsked) ImGui::SetScrollHereY(0.0f); // a pin (Alt+click) brings its panel into view
            drawPixelPanel(session_, panelState_);
        }
        if (panelState_.materialToOpen >= 0) { // the Pixel panel's "open": that material, next frame
            materialsPanel_.openMaterial(static_cast<std::size_t>(panelState_.materialToOpen));
            panelState_.panelsToOpen.push_back("materials");
            panelState_.materialToOpen = -1;
        }
        bool sceneOpen = rendering && header("Scene");
        if (sceneOpen) drawScenePanel(session_, panelState_);
        if (rendering && header("Environment")) drawEnvironmentPanel(session_, panelState_);
        if (rendering && header("Materials")) materialsPanel_.draw(session_);
        if (rendering && header("Lights")) drawLightsPanel(session_);
        if (rendering && header("Camera")) drawCameraPanel(session_);
        if (header("Interface")) drawInterfacePanel(panelState_);
        if (header("Help")) drawHelpPanel();
        ImGui::SetNextItemOpen(warpVisualizer_.active(), ImGuiCond_Once);
        if (ImGui::CollapsingHeader("Warp visualizer")) warpVisualizer_.drawControls();
        // A load error must be seen even with the Scene panel closed (open, it shows it itself).
        if (!model.sceneError.empty() && !sceneOpen) {
            ImGui::Separator();
            ImGui::PushTextWrapPos(0.0f);
            ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", printableText(model.sceneError).c_str());
            ImGui::PopTextWrapPos();
        }
        ImGui::PopItemWidth();
        sidebarWidth_ = ImGui::GetWindowWidth(); // the user may drag its right edge
    }
    ImGui::End();
}

// The sidebar's sections the user popped out, each in its own window over the image.
void ViewerWindow::drawDetachedWindows() {
    const float em = ImGui::GetFontSize();
    DetachedWindows& detached = panelState_.detached;
    detached.drawWindow(DetachableSection::PathsTable, ImVec2(0.0f, 26.0f * em), ImVec2(1.0f, 1.0f),
                        [&] { drawTracedPathsTable(session_, panelState_, true); });
    detached.drawWindow(DetachableSection::LightPaths, ImVec2(26.0f * em, 0.0f), ImVec2(1.0f, 0.0f), [&] {
        ImGui::PushItemWidth(-ImGui::CalcTextSize("bounces k").x - 2.0f * ImGui::GetStyle().ItemInnerSpacing.x);
        drawLightPathControls(session_.model());
        ImGui::PopItemWidth();
    });
    detached.drawWindow(DetachableSection::Compare, ImVec2(26.0f * em, 0.0f), ImVec2(1.0f, 0.3f), [&] {
        ImGui::PushItemWidth(-ImGui::CalcTextSize("MAX_DEPTH").x - 2.0f * ImGui::GetStyle().ItemInnerSpacing.x);
        drawCompareControls(session_.model());
        ImGui::PopItemWidth();
    });
}

void ViewerWindow::drawCompareLabels() {
    if (!session_.comparing()) return;
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    float top = 8.0f;
    auto label = [&](ViewerSession::Side side, float x, bool alignRight) {
        const RenderSettings& settings = session_.settings(side);
        ViewerSession::ViewStats stats = session_.stats(side);
        char heading[128];
        std::snprintf(heading, sizeof(heading), "%s / %s / depth %d", integratorName(settings.integrator),
                      samplerModeName(settings.sampler), settings.maxDepth);
        std::string text = heading;
        if (std::string content = imageContentLabel(settings, stats.denoised, stats.denoisedSamples); !content.empty()) text += " / " + content;
        if (DisplayView view = session_.displaySettings(side).view; view != DisplayView::Image)
            text += std::string(" / ") + displayViewNames().entry(view).displayLabel();
        // The noise is the raw accumulation's, also on a denoised side (the Stats panel says so);
        // beside it the true error where a reference is loaded, which alone sees a missing light.
        text += "\n" + splitLabelNumbers(stats.samples, stats.renderSeconds, stats.error,
                                         stats.trueError ? &*stats.trueError : nullptr, stats.errorSamples);
        ImVec2 size = ImGui::CalcTextSize(text.c_str());
        ImVec2 position(alignRight ? x - size.x - 10.0f : x + 10.0f, top);
        draw->AddRectFilled(ImVec2(position.x - 4, position.y - 2), ImVec2(position.x + size.x + 4, position.y + size.y + 2),
                            IM_COL32(0, 0, 0, 160), 3.0f);
        draw->AddText(position, IM_COL32(255, 255, 255, 255), text.c_str());
    };
    float divider = static_cast<float>(session_.dividerX()) / framebufferScale_.x;
    label(ViewerSession::Side::Left, divider, true);
    label(ViewerSession::Side::Right, divider, false);
}

// What the image shows when it is not simply the render at the window's size: a low-resolution
// preview before the first full sample, or a render kept through a resize and shown scaled; what
// it shows when it is not the plain radiance; and feedback that must be seen with the sidebar
// hidden (Tab) or scrolled: a scene or shader file that did not apply, what F12 saved.
void ViewerWindow::drawImageNotes() {
    std::string note;
    const PathTracer& tracer = session_.tracer(ViewerSession::Side::Left);
    if (glm::ivec2 size = tracer.shownPreviewSize(); size.x > 0) {
        note = "preview " + std::to_string(size.x) + "x" + std::to_string(size.y) + ", first full sample " +
               std::to_string(tracer.nextRow() * 100 / std::max(1, tracer.imageSize().y)) + "% done";
    }
    glm::ivec2 rendered = session_.renderSize(), wanted = session_.wantedRenderSize();
    if (rendered != wanted) {
        if (!note.empty()) note += "\n";
        note += "render " + std::to_string(rendered.x) + "x" + std::to_string(rendered.y) + " shown scaled; R renders at " +
                std::to_string(wanted.x) + "x" + std::to_string(wanted.y);
    }
    if (const ImageZoom& zoom = session_.model().zoom; !zoom.fit()) { // the pixel zoom, and how to leave it
        char text[64];
        std::snprintf(text, sizeof text, "zoom %g:1 (0: fit)", static_cast<double>(zoom.scale));
        note += (note.empty() ? "" : "\n") + std::string(text);
        // The render pixel under the pointer, as Alt+click would pin it.
        glm::dvec2 cursor;
        glfwGetCursorPos(window_, &cursor.x, &cursor.y);
        if (std::optional<glm::ivec2> pixel = session_.pixelAtFramebuffer(framebufferAt(cursor)))
            note += ", pixel " + std::to_string(pixel->x) + " " + std::to_string(pixel->y);
    }
    PixelRect area = session_.imageArea();
    float left = static_cast<float>(area.origin.x) / framebufferScale_.x + 10.0f;
    float right = static_cast<float>(area.origin.x + area.size.x) / framebufferScale_.x - 10.0f;
    float bottom = ImGui::GetIO().DisplaySize.y - 10.0f;
    if (!note.empty()) drawImageNote(note, ImVec2(left, bottom), false, true, IM_COL32(255, 255, 255, 255));
    // What the image shows when it is not the plain render, readable after Tab hides the sidebar
    // (the split view's labels say it for each side).
    if (!session_.comparing()) {
        const RenderSettings& settings = session_.settings(ViewerSession::Side::Left);
        std::string content = imageContentLabel(settings, session_.showsDenoised(ViewerSession::Side::Left),
                                                session_.tracer(ViewerSession::Side::Left).denoisedSampleCount());
        if (DisplayView view = session_.model().display.view; view != DisplayView::Image)
            content += (content.empty() ? "" : ", ") + std::string(displayViewNames().entry(view).displayLabel());
        if (!content.empty()) drawImageNote(content, ImVec2(left, 8.0f), false, false, IM_COL32(255, 255, 255, 255));
    }
    // Feedback the sidebar may hide: a save that did not apply, the files F12 wrote.
    const ViewerModel& model = session_.model();
    std::string failure = reloadFailureNote(model.sceneError, model.shaderError);
    if (!failure.empty()) drawImageNote(failure, ImVec2(right, bottom), true, true, IM_COL32(255, 120, 110, 255));
    bool noticeShown = std::chrono::duration<double>(Clock::now() - panelState_.imageNoticeSince).count() < kImageNoticeSeconds;
    if (!panelState_.imageNotice.empty() && noticeShown) {
        float above = failure.empty() ? 0.0f : ImGui::CalcTextSize(failure.c_str()).y + 10.0f;
        drawImageNote(panelState_.imageNotice, ImVec2(right, bottom - above), true, true,
                      panelState_.imageNoticeFailed ? IM_COL32(255, 120, 110, 255) : IM_COL32(140, 235, 140, 255));
    }
}

// A line or two on a dark box over the image, placed by the corner at `anchor` (window
// coordinates): its right edge there when alignRight, its bottom when alignBottom.
// The colour bar of an error or difference view, in the view's bottom-right corner (the right
// side's view in a split, where the left shows the image), and why a view shows the image instead.
void ViewerWindow::drawLegend() {
    ViewerSession::Side side = session_.comparing() ? ViewerSession::Side::Right : ViewerSession::Side::Left;
    PixelRect area = session_.viewArea();
    ScreenRect view{{static_cast<float>(area.origin.x) / framebufferScale_.x,
                     static_cast<float>(framebufferSize_.y - area.origin.y - area.size.y) / framebufferScale_.y},
                    glm::vec2(area.size) / framebufferScale_};
    std::string problem = session_.viewProblem(side);
    if (!problem.empty()) {
        drawImageNote(problem, ImVec2(view.topLeft.x + view.size.x - 10.0f, view.topLeft.y + view.size.y - 10.0f), true, true,
                      IM_COL32(255, 200, 80, 255));
        return;
    }
    drawErrorLegend(*ImGui::GetForegroundDrawList(), session_.displaySettings(side), view, session_.tracer(side).sampleCount());
}

void ViewerWindow::drawImageNote(const std::string& text, ImVec2 anchor, bool alignRight, bool alignBottom, ImU32 colour) {
    ImVec2 size = ImGui::CalcTextSize(text.c_str());
    ImVec2 position(alignRight ? anchor.x - size.x : anchor.x, alignBottom ? anchor.y - size.y : anchor.y);
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    draw->AddRectFilled(ImVec2(position.x - 4, position.y - 2), ImVec2(position.x + size.x + 4, position.y + size.y + 2),
                        IM_COL32(0, 0, 0, 160), 3.0f);
    draw->AddText(position, colour, text.c_str());
}

void ViewerWindow::drawUi() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (sidebarVisible_) drawSidebar();
    if (helpOpen_) {
        ImVec2 display = ImGui::GetIO().DisplaySize;
        ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
        // A fixed width and an auto-fitted height (0): with AlwaysAutoResize the table's wrapping
        // column and the window's width fed each other until the column was one letter wide.
        float width = std::min(display.x - 20.0f, 36.0f * ImGui::GetFontSize());
        ImGui::SetNextWindowSize(ImVec2(width, 0.0f), ImGuiCond_Always);
        if (ImGui::Begin("Help", &helpOpen_, ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse)) drawHelpPanel();
        ImGui::End();
    }
    if (!warpVisualizer_.active()) {
        drawDetachedWindows();
        drawCompareLabels();
        drawLegend();
        drawImageNotes();
        drawTracedPaths();
        drawPinnedPixelMarker();
    }
    drawUnsavedEditsDialog(session_, panelState_);
    if (warpVisualizer_.active()) {
        warpVisualizer_.drawLabels();
        warpVisualizer_.handleMouse();
    }
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

// The frame's phases, in order: events, timing, input and model, image, UI, hand-off.

// Waits for input (briefly when idle: paused or target reached, so files are still checked) and
// takes the close button like Esc. False: nothing to draw this time (minimized, or quitting).
bool ViewerWindow::waitForEvents(bool busy) {
    if (busy) glfwPollEvents(); else glfwWaitEventsTimeout(0.25);
    if (glfwWindowShouldClose(window_)) { // the close button: asks first, like Esc
        glfwSetWindowShouldClose(window_, GLFW_FALSE);
        panelState_.unsavedEdits.request(session_, UnsavedEditsPrompt::Action::Quit);
        if (panelState_.unsavedEdits.quitConfirmed()) return false;
    }
    glfwGetFramebufferSize(window_, &framebufferSize_.x, &framebufferSize_.y);
    if (framebufferSize_.x <= 0 || framebufferSize_.y <= 0) { // minimized
        glfwWaitEvents();
        return false;
    }
    applyInterface();
    return true;
}

// A change of the monitor's scale or of the user's preferences restyles the panels; a change the
// user made is kept for the next run (UserPreferences.h).
void ViewerWindow::applyInterface() {
    const UserPreferences& wanted = panelState_.preferences;
    if (!events(window_).contentScaleChanged && wanted == appliedPreferences_) return;
    const float scale = events(window_).contentScale * wanted.uiScale;
    applyInterfaceStyle(scale, wanted.highContrast);
    sidebarWidth_ = kSidebarWidth * scale;
    events(window_).contentScaleChanged = false;
    appliedPreferences_ = wanted;
    keepPreferences();
}

// Written when they differ from what the file holds (loaded or last saved), so a run that changes
// nothing writes nothing.
void ViewerWindow::keepPreferences() {
    if (!preferencesPath_ || panelState_.preferences == savedPreferences_) return;
    savedPreferences_ = panelState_.preferences;
    try {
        savePreferences(*preferencesPath_, savedPreferences_);
    } catch (const std::exception& e) {
        printMessage(std::string("warning: ") + e.what());
    }
}

// The time since the last frame, smoothed into the frame time and the part of it that is not
// path tracing (what the next frame's tracing budget leaves room for). Returns the raw seconds.
double ViewerWindow::timeFrame() {
    Clock::time_point now = Clock::now();
    double seconds = std::chrono::duration<double>(now - lastFrame_).count();
    lastFrame_ = now;
    frameSeconds_ = frameSeconds_ == 0.0 ? seconds : 0.9 * frameSeconds_ + 0.1 * seconds;
    if (lastTracingSeconds_ > 0.0) { // an idle frame's wait for events is no overhead
        double overhead = std::max(0.0, seconds - lastTracingSeconds_);
        overheadSeconds_ = overheadSeconds_ == 0.0 ? overhead : 0.9 * overheadSeconds_ + 0.1 * overhead;
    }
    lastTracingSeconds_ = 0.0;
    return seconds;
}

// The scene and settings react to what changed (edits, files on disk); a shader error of the
// split view's second program turns the split view off rather than ending the viewer.
void ViewerWindow::updateSession() {
    session_.pollFiles();
    try {
        session_.update();
    } catch (const ShaderError& e) {
        session_.model().shaderError = e.what();
        session_.model().compare.enabled = false;
    }
}

// Traces within the frame's budget and displays the image (or the warp view, while the path
// tracer pauses), beside the sidebar rather than under it.
void ViewerWindow::drawImage() {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, framebufferSize_.x, framebufferSize_.y);
    glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (warpVisualizer_.active()) {
        PixelRect area = session_.imageArea();
        warpVisualizer_.draw(area.origin, area.size, framebufferSize_, framebufferScale_);
        return;
    }
    if (session_.accumulating() || session_.denoisePending())
        lastTracingSeconds_ = session_.renderFrame(std::max(kMinTracingSeconds, kFrameSeconds - overheadSeconds_));
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    session_.display();
}

// `--frames N --screenshot PATH`: after N frames, once something is shown (a slow GPU spreads a
// sample over several frames), writes the window and ends the viewer (true).
bool ViewerWindow::frameScreenshotDone(int frame, Clock::time_point start) {
    bool somethingShown = warpVisualizer_.active() || session_.stats(ViewerSession::Side::Left).samples > 0;
    if (options_.frames <= 0 || frame < options_.frames || !somethingShown) return false;
    writePng(options_.screenshotPath, readWindow(framebufferSize_), session_.provenance(ViewerSession::Side::Left));
    double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    std::fprintf(stderr, "ptview: wrote %s after %d frames (%d spp) in %.2f s, %.1f ms per frame\n",
                 options_.screenshotPath.c_str(), frame, session_.stats(ViewerSession::Side::Left).samples, elapsed,
                 elapsed / frame * 1e3);
    return true;
}

int ViewerWindow::run(std::optional<ScriptRunner>& script) {
    const Clock::time_point start = lastFrame_ = Clock::now();
    int frame = 0;
    while (!panelState_.unsavedEdits.quitConfirmed()) {
        // A denoise still to come (its bands run over frames, also after the samples stop) is work too.
        bool busy = session_.accumulating() || session_.denoisePending();
        if (!waitForEvents(busy || (script && !script->quitRequested()))) continue;
        double seconds = timeFrame();

        handleKeys();
        if (panelState_.unsavedEdits.quitConfirmed()) break;
        if (!warpVisualizer_.active()) handleMouseAndFlight(seconds);
        layout();
        if (script) {
            script->step(session_, panelState_);
            if (script->quitRequested()) break;
        }
        updateSession();

        drawImage();
        drawUi();
        // After the panels, so that this frame's edits are in; one step once the edit ends.
        session_.recordEdits(editInProgress());
        updateTitle();

        if (script) {
            if (std::optional<std::filesystem::path> path = script->takeWindowScreenshot()) {
                writePng(*path, readWindow(framebufferSize_), session_.provenance(ViewerSession::Side::Left));
                std::fprintf(stderr, "ptview: wrote %s\n", path->string().c_str());
            }
            script->frameDisplayed();
        }
        if (frameScreenshotDone(++frame, start)) break;
        glfwSwapBuffers(window_);
    }
    keepPreferences(); // a change in the last frame (a script's last command) too
    return script ? script->exitCode() : 0;
}

// ---- The viewer's phases, as Dear ImGui's example_glfw_opengl3 has them: init the window, init
// ImGui, loop, shut down. The shutdown is the destructors' work, so every return takes it.

// GLFW from glfwInit to glfwTerminate.
class GlfwLibrary {
public:
    GlfwLibrary() : initialized_(glfwInit() == GLFW_TRUE) {}
    ~GlfwLibrary() {
        if (initialized_) glfwTerminate();
    }
    GlfwLibrary(const GlfwLibrary&) = delete;
    GlfwLibrary& operator=(const GlfwLibrary&) = delete;
    bool initialized() const { return initialized_; }

private:
    bool initialized_;
};

using WindowHandle = std::unique_ptr<GLFWwindow, void (*)(GLFWwindow*)>;

// A window for the scene's camera, centred in the monitor's work area, its OpenGL 4.1 core context
// current and loaded; null, with the reason on stderr, when there is none.
WindowHandle openWindow(glm::ivec2 cameraResolution) {
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE); // required on macOS
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);      // HiDPI: window size in logical units
    glm::ivec2 workOrigin(0), workArea(0); // none known: only the 768-row rule applies
    float monitorScale = 1.0f;
    if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
        glfwGetMonitorWorkarea(monitor, &workOrigin.x, &workOrigin.y, &workArea.x, &workArea.y);
        glfwGetMonitorContentScale(monitor, &monitorScale, nullptr);
    }
    // GLFW_SCALE_TO_MONITOR multiplies the size asked for by the content scale.
    glm::ivec2 windowSize = initialWindowSize(cameraResolution, kSidebarWidth,
                                              glm::ivec2(glm::vec2(workArea) / std::max(monitorScale, 1.0f)));
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE); // shown once placed in the work area
    WindowHandle window(glfwCreateWindow(windowSize.x, windowSize.y, "ptview", nullptr, nullptr), glfwDestroyWindow);
    if (!window) {
        std::cerr << "ptview: cannot create an OpenGL 4.1 core window\n";
        return window;
    }
    if (workArea.x > 0) {
        glm::ivec2 actual;
        glfwGetWindowSize(window.get(), &actual.x, &actual.y);
        glfwSetWindowPos(window.get(), workOrigin.x + std::max(0, (workArea.x - actual.x) / 2),
                         workOrigin.y + std::max(0, (workArea.y - kDecorationAllowance - actual.y) / 2));
    }
    glfwShowWindow(window.get());
    glfwMakeContextCurrent(window.get());
    glfwSwapInterval(0); // the frame budget paces us; vsync would cap the sample rate
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress))) {
        std::cerr << "ptview: cannot load OpenGL functions\n";
        window.reset();
    }
    return window;
}

// Our callbacks on the window; set before ImGui's, which chain to them.
void listenToInput(GLFWwindow* window, InputEvents& inputEvents) {
    glfwSetWindowUserPointer(window, &inputEvents);
    glfwSetKeyCallback(window, onKey);
    glfwSetScrollCallback(window, onScroll);
    glfwSetWindowContentScaleCallback(window, onContentScale);
    glfwGetWindowContentScale(window, &inputEvents.contentScale, nullptr);
    inputEvents.contentScaleChanged = true;
}

// Dear ImGui on the window, from its context's creation to its destruction.
class ImGuiOnWindow {
public:
    explicit ImGuiOnWindow(GLFWwindow* window) {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr; // no imgui.ini litter in the user's directory
        ImGui_ImplGlfw_InitForOpenGL(window, true);
        ImGui_ImplOpenGL3_Init("#version 410 core");
    }
    ~ImGuiOnWindow() {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
    ImGuiOnWindow(const ImGuiOnWindow&) = delete;
    ImGuiOnWindow& operator=(const ImGuiOnWindow&) = delete;
};

} // namespace

int runViewer(const ViewerOptions& requested) {
    ViewerOptions options = requested; // an image to open replaces the settings with its own
    // The window is PNG whatever the name says, so the name must say PNG; and a path that cannot
    // be written is refused before any window opens.
    if (!options.screenshotPath.empty() && !checkOutputPath(options.screenshotPath, {".png"})) return kExitBadInput;
    std::optional<ScriptRunner> script;
    if (!options.scriptPath.empty()) {
        try {
            script.emplace(loadViewerScript(options.scriptPath));
        } catch (const ScriptError& e) {
            printMessage(e.what());
            return kExitBadInput;
        }
    }
    std::optional<Provenance> from; // `ptview shot.png`: the scene and settings it was rendered with
    ReadScope scope;                // what the load refused, for the question below
    auto load = [&options, &from, &scope]() {
        return isProvenanceImage(options.scenePath)
                   ? loadSceneInputFromImage(options.scenePath, from, options.allowedDirectories, &scope)
                   : loadSceneInput(options.scenePath, options.allowedDirectories, &scope);
    };
    std::optional<SceneInput> input = load();
    // A file outside the folders a sent file may read is a question for the user; anything else
    // wrong is bad input, reported before any window opens.
    if (!input && scope.refusedFiles().empty()) return kExitBadInput;
    // Checked before any window opens: bad input leaves with the message and exit 2. An image's
    // recorded display and view are in `from` once it loaded.
    ToneMapper toneMapper = from ? from->recipe.display.toneMapper : options.display.toneMapper;
    const std::optional<std::shared_ptr<const OcioView>> ocio =
        resolveOcioView(requested.ocio, from ? &from->recipe : nullptr, options.scenePath, toneMapper);
    if (!ocio) return kExitBadInput;

    // Init the window. Destroyed in the reverse order: ImGui, the window, GLFW.
    glfwSetErrorCallback(reportGlfwError);
    GlfwLibrary glfw;
    if (!glfw.initialized()) {
        std::cerr << "ptview: cannot open a window (no display?); `ptview render` renders without one\n";
        return kExitRuntimeError;
    }
    WindowHandle window = openWindow(input ? input->scene.camera.resolution : CameraDesc().resolution);
    if (!window) return kExitRuntimeError;
    InputEvents inputEvents;
    listenToInput(window.get(), inputEvents);

    // Init ImGui.
    ImGuiOnWindow imgui(window.get());

    // Each folder the scene wants outside its own is asked about once, then the load is tried again.
    while (!input) {
        // The last refusal is the one that stopped the load (earlier ones, of files a mesh's
        // library names but ptview does not need, were only warnings).
        const std::filesystem::path refused = scope.refusedFiles().back();
        const std::filesystem::path folder = refused.parent_path();
        const std::string question = printableText(options.scenePath) + " wants to read " + printableText(refused.string()) +
                                     ", outside the folders a file from someone else may read.\n\nAllow ptview to read files in " +
                                     printableText(folder.string()) + " for this session?";
        printMessage("asking in the window whether to read " + folder.string());
        auto takePressedKeys = [&inputEvents] {
            std::vector<int> keys;
            for (const KeyPress& press : std::exchange(inputEvents.pressedKeys, {})) keys.push_back(press.key);
            return keys;
        };
        if (!askToAllowFolder(window.get(), question, takePressedKeys)) {
            printMessage("not allowed: " + folder.string() + " (--allow-dir DIR allows it)");
            return kExitBadInput;
        }
        options.allowedDirectories.push_back(folder);
        input = load();
        if (!input && scope.refusedFiles().empty()) return kExitBadInput;
    }
    if (from) applyRecipe(from->recipe, options);

    // Loop, until the user or the script quits.
    try {
        ViewerSession session(std::move(*input), options.settings, options.display, options.shaderDir,
                              options.program);
        session.model().denoise = options.denoise; // --denoise, or the denoiser an opened image was made with
        if (*ocio && !session.setOcioView({(*ocio)->configPath().string(), (*ocio)->display(), (*ocio)->view()})) {
            printMessage(session.model().ocioError);
            return kExitBadInput;
        }
        if (!options.referencePath.empty() && !session.setReference(options.referencePath)) {
            printMessage(session.model().sceneError);
            return kExitBadInput;
        }
        ViewerWindow viewer(window.get(), session, options);
        return viewer.run(script);
    } catch (const std::exception& e) {
        printMessage(e.what());
        return kExitRuntimeError;
    }
}

} // namespace ptview
