#include <ptview/window/AllowFolderPrompt.h>

#include <glad/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <optional>

namespace ptview {
namespace {

// The answer a key gave while the question is up, and the key callback it displaced (ImGui's).
// ImGui reads keys as held down at a frame's start; a key tapped while a frame draws (long, on a
// software rasterizer under load) arrives pressed and released in one poll and never shows as
// held, so the press is recorded here as it arrives. One question at a time.
std::optional<bool> keyAnswer;
GLFWkeyfun displacedKeyCallback = nullptr;

void recordAnswerKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
    if (action == GLFW_PRESS && (key == GLFW_KEY_ENTER || key == GLFW_KEY_KP_ENTER)) keyAnswer = true;
    if (action == GLFW_PRESS && key == GLFW_KEY_ESCAPE) keyAnswer = false;
    if (displacedKeyCallback) displacedKeyCallback(window, key, scancode, action, mods);
}

} // namespace

bool askToAllowFolder(GLFWwindow* window, const std::string& question) {
    constexpr const char* kTitle = "Read a folder outside?";
    std::optional<bool> answer;
    keyAnswer.reset();
    displacedKeyCallback = glfwSetKeyCallback(window, recordAnswerKey);
    while (!answer) {
        glfwWaitEventsTimeout(0.1);
        if (glfwWindowShouldClose(window)) {
            glfwSetWindowShouldClose(window, GLFW_FALSE); // this question only: the viewer decides next
            answer = false;
            break;
        }
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        const ImVec2 display = ImGui::GetIO().DisplaySize;
        ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
        ImGui::OpenPopup(kTitle);
        if (ImGui::BeginPopupModal(kTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
            ImGui::PushTextWrapPos(ImGui::GetFontSize() * 34.0f);
            ImGui::TextUnformatted(question.c_str());
            ImGui::PopTextWrapPos();
            if (ImGui::Button("Allow")) answer = true;
            ImGui::SameLine();
            if (ImGui::Button("Cancel")) answer = false;
            ImGui::TextDisabled("keys: Enter allow, Esc cancel");
            ImGui::EndPopup();
        }
        ImGui::Render();
        int width = 0, height = 0;
        glfwGetFramebufferSize(window, &width, &height);
        glViewport(0, 0, width, height);
        glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        glfwSwapBuffers(window);
        if (!answer) answer = keyAnswer;
    }
    glfwSetKeyCallback(window, displacedKeyCallback);
    return *answer;
}

} // namespace ptview
