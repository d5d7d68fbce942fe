#include "Viewer.h"

#include "EnvironmentMap.h"
#include "ImageIO.h"
#include "MaterialsPanel.h"
#include "PathTracer.h"
#include "Readback.h"
#include "Scene.h"
#include "SceneInput.h"
#include "WarpVisualizer.h"

#include <glad/gl.h>
// GLFW after glad, so it does not pull in the system GL header.
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>

namespace ptview {
namespace {

using Clock = std::chrono::steady_clock;

// Samples per displayed frame are added while the frame's GPU time stays under this budget, so
// a fast GPU converges quickly and a slow one still redraws the UI.
constexpr double kFrameBudgetSeconds = 0.016;
constexpr int kMaxSamplesPerFrame = 64;

struct FrameStats {
    double frameSeconds = 0.0; // smoothed time between displayed frames
    double samplesPerSecond = 0.0;
};

// Installed before ImGui's own callbacks, which chain to it.
void onKey(GLFWwindow* window, int key, int /*scancode*/, int action, int /*mods*/) {
    if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS && !ImGui::GetIO().WantCaptureKeyboard)
        glfwSetWindowShouldClose(window, GLFW_TRUE);
}

void reportGlfwError(int code, const char* description) {
    std::fprintf(stderr, "ptview: GLFW error %d: %s\n", code, description);
}

glm::ivec2 initialWindowSize(glm::ivec2 resolution) {
    // Small scene resolutions would give a window too small for the panel.
    int longest = std::max(resolution.x, resolution.y);
    float scale = longest < 768 ? 768.0f / static_cast<float>(longest) : 1.0f;
    return glm::ivec2(glm::vec2(resolution) * scale);
}

ImageRgba8 readWindow(glm::ivec2 size) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    ImageRgba8 image = readColorRgba8(size);
    for (size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255; // the window is opaque
    return image;
}

void drawRenderPanel(const Scene& scene, PathTracer& tracer, RenderSettings& settings, float& exposureStops,
                     const FrameStats& stats) {
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.8f);
    ImGui::Begin("Render", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::Text("%s", scene.path.filename().string().c_str());
    ImGui::Text("%d x %d, %d spp", tracer.imageSize().x, tracer.imageSize().y, tracer.sampleCount());
    ImGui::Text("%.1f ms per frame", stats.frameSeconds * 1e3);
    ImGui::Text("%.2f M samples/s", stats.samplesPerSecond * 1e-6);
    ImGui::Separator();
    const IntegratorName* current = &integratorNames()[0];
    for (const IntegratorName& entry : integratorNames())
        if (entry.integrator == settings.integrator) current = &entry;
    if (ImGui::BeginCombo("integrator", current->label)) {
        for (const IntegratorName& entry : integratorNames())
            if (ImGui::Selectable(entry.label, entry.integrator == settings.integrator)) settings.integrator = entry.integrator;
        ImGui::EndCombo();
    }
    ImGui::SliderInt("MAX_DEPTH", &settings.maxDepth, 0, 64);
    if (ImGui::BeginCombo("sampler", samplerModeName(settings.sampler))) {
        for (const SamplerModeName& entry : samplerModeNames())
            if (ImGui::Selectable(entry.name, entry.mode == settings.sampler)) settings.sampler = entry.mode;
        ImGui::EndCombo();
    }
    ImGui::SliderFloat("exposure (stops)", &exposureStops, -10.0f, 10.0f, "%.1f");
    if (ImGui::Button("Restart")) tracer.restart();
    ImGui::End();
}

} // namespace

int runViewer(const ViewerOptions& options) {
    std::optional<SceneInput> input = loadSceneInput(options.scenePath);
    if (!input) return kExitBadInput;
    Scene scene = std::move(input->scene);

    glfwSetErrorCallback(reportGlfwError);
    if (!glfwInit()) {
        std::cerr << "ptview: cannot open a window (no display?); `ptview render` renders without one\n";
        return kExitRuntimeError;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE); // required on macOS
    glm::ivec2 windowSize = initialWindowSize(scene.camera.resolution);
    GLFWwindow* window = glfwCreateWindow(windowSize.x, windowSize.y, "ptview", nullptr, nullptr);
    if (!window) {
        std::cerr << "ptview: cannot create an OpenGL 4.1 core window\n";
        glfwTerminate();
        return kExitRuntimeError;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(0); // the frame budget paces us; vsync would cap the sample rate
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress))) {
        std::cerr << "ptview: cannot load OpenGL functions\n";
        glfwTerminate();
        return kExitRuntimeError;
    }

    glfwSetKeyCallback(window, onKey);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // no imgui.ini litter in the user's directory
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 410 core");

    int exitCode = 0;
    try {
        PathTracer tracer;
        tracer.setScene(scene, input->environmentMapOrNull());
        RenderSettings settings = options.settings;
        float exposureStops = options.exposureStops;
        FrameStats stats;
        WarpVisualizer warpVisualizer(options.warp);
        warpVisualizer.setActive(options.showWarp);
        MaterialsPanel materialsPanel(scene);
        Clock::time_point lastFrame = Clock::now();
        int frame = 0;

        while (!glfwWindowShouldClose(window)) {
            glfwPollEvents();
            glm::ivec2 framebufferSize;
            glfwGetFramebufferSize(window, &framebufferSize.x, &framebufferSize.y);
            if (framebufferSize.x <= 0 || framebufferSize.y <= 0) { // minimized
                glfwWaitEvents();
                continue;
            }
            tracer.setImageSize(framebufferSize);
            tracer.setSettings(settings);

            int samplesThisFrame = 0;
            if (warpVisualizer.active()) {
                glBindFramebuffer(GL_FRAMEBUFFER, 0);
                warpVisualizer.draw(framebufferSize); // the path tracer pauses meanwhile
            } else {
                Clock::time_point renderStart = Clock::now();
                do {
                    tracer.renderSample();
                    glFinish();
                    ++samplesThisFrame;
                } while (samplesThisFrame < kMaxSamplesPerFrame &&
                         std::chrono::duration<double>(Clock::now() - renderStart).count() < kFrameBudgetSeconds);
                glBindFramebuffer(GL_FRAMEBUFFER, 0);
                tracer.display(framebufferSize, exposureStops);
            }

            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            if (materialsPanel.draw(scene)) tracer.setMaterials(scene.materials); // the next frame shows it
            warpVisualizer.drawPanel();
            drawRenderPanel(scene, tracer, settings, exposureStops, stats); // last: it starts focused
            if (warpVisualizer.active()) warpVisualizer.handleMouse();
            ImGui::Render();
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

            ++frame;
            if (options.frames > 0 && frame >= options.frames) {
                writePng(options.screenshotPath, readWindow(framebufferSize));
                std::fprintf(stderr, "ptview: wrote %s after %d frames (%d spp)\n", options.screenshotPath.c_str(),
                             frame, tracer.sampleCount());
                break;
            }
            glfwSwapBuffers(window);

            Clock::time_point now = Clock::now();
            double seconds = std::chrono::duration<double>(now - lastFrame).count();
            lastFrame = now;
            stats.frameSeconds = stats.frameSeconds == 0.0 ? seconds : 0.9 * stats.frameSeconds + 0.1 * seconds;
            double samples = static_cast<double>(framebufferSize.x) * framebufferSize.y * samplesThisFrame;
            stats.samplesPerSecond = samples / std::max(seconds, 1e-6);
        }
    } catch (const std::exception& e) {
        std::cerr << "ptview: " << e.what() << "\n";
        exitCode = kExitRuntimeError;
    }

    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    return exitCode;
}

} // namespace ptview
