#pragma once
// Sections of the sidebar the user can pop out into their own window, to give a wide table or a
// set of teaching controls room over the image (on a projector, beside the picture they change).
// Popped out, a section is drawn in a movable, resizable window after the sidebar, and its place
// in the sidebar says where it went; closing the window puts it back.

#include <ptview/model/DetachableSection.h>

#include <imgui.h>

#include <array>
#include <string>

namespace ptview {

class DetachedWindows {
public:
    bool isOut(DetachableSection section) const { return state(section).out; }
    void setOut(DetachableSection section, bool out) { state(section).out = out; }

    // In the sidebar, at the section's start: a small "pop out" button, or, while it is out, a line
    // saying so with "put back". True: draw the section here.
    bool drawInSidebar(DetachableSection section);
    // After the sidebar: the section's window while it is out (drawContent fills it). Closing it
    // puts the section back in the sidebar.
    // First shown where `corner` says, as a fraction of the window (1, 0: the top right corner; 1,
    // 0.5: the middle of the right edge), so sections popped out together do not cover each other;
    // at the right, where a window covers least of a centred subject. A 0 in firstSize fits that
    // side to the content (ImGui measures it on the first frames).
    template <typename DrawContent>
    void drawWindow(DetachableSection section, ImVec2 firstSize, ImVec2 corner, DrawContent drawContent) {
        if (!isOut(section)) return;
        const ImGuiIO& io = ImGui::GetIO();
        const float margin = 12.0f;
        ImGui::SetNextWindowPos(ImVec2(margin + corner.x * (io.DisplaySize.x - 2.0f * margin),
                                       margin + corner.y * (io.DisplaySize.y - 2.0f * margin)),
                                ImGuiCond_FirstUseEver, corner);
        ImGui::SetNextWindowSize(firstSize, ImGuiCond_FirstUseEver);
        bool open = true;
        if (ImGui::Begin(detachableSectionInfo(section).title, &open, ImGuiWindowFlags_NoCollapse)) {
            drawContent();
            Window& window = state(section);
            window.position = ImGui::GetWindowPos();
            window.size = ImGui::GetWindowSize();
        }
        ImGui::End();
        if (!open) setOut(section, false);
    }
    // "paths-table@X,Y,WxH ..." of the windows drawn out (window coordinates), "none" when none:
    // for the status line of scripts and the window tests.
    std::string describe() const;

private:
    struct Window {
        bool out = false;
        ImVec2 position{0.0f, 0.0f}, size{0.0f, 0.0f}; // as last drawn; size 0: not drawn yet
    };
    Window& state(DetachableSection section) { return windows_[static_cast<size_t>(section)]; }
    const Window& state(DetachableSection section) const { return windows_[static_cast<size_t>(section)]; }

    std::array<Window, 3> windows_;
};

} // namespace ptview
