#include <ptview/window/AllowFolderPrompt.h>

#include <glad/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <optional>

namespace ptview {

bool askToAllowFolder(GLFWwindow* window, const std::string& question,
                      const std::function<std::vector<int>()>& takePressedKeys) {
    constexpr const char* kTitle = "Read a folder outside?";
    std::optional<bool> answer;
    takePressedKeys(); // keys pressed before the question are no answer to it
    while (!answer) {
        glfwWaitEventsTimeout(0.1);
        if (glfwWindowShouldClose(window)) {
            glfwSetWindowShouldClose(window, GLFW_FALSE); // this question only: the viewer decides next
            return false;
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
        for (int key : takePressedKeys()) {
            if (answer) break;
            if (key == GLFW_KEY_ENTER || key == GLFW_KEY_KP_ENTER) answer = true;
            if (key == GLFW_KEY_ESCAPE) answer = false;
        }
    }
    return *answer;
}

} // namespace ptview
