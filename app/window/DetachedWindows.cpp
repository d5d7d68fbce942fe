#include <ptview/window/DetachedWindows.h>

#include <ptview/window/PanelWidgets.h>

#include <cstdio>

namespace ptview {

bool DetachedWindows::drawInSidebar(DetachableSection section) {
    ImGui::PushID(detachableSectionInfo(section).name);
    bool here = !isOut(section);
    if (here) {
        // At the right end of the line above the section, where it takes no row of its own.
        if (ImGui::SmallButton("pop out")) setOut(section, true);
        if (ImGui::IsItemHovered())
            wrappedTooltip(std::string("show \"") + detachableSectionInfo(section).title +
                           "\" in its own window (move and resize it; close it to put it back here)");
    } else {
        ImGui::TextDisabled("(in its own window)");
        ImGui::SameLine();
        if (ImGui::SmallButton("put back")) setOut(section, false);
    }
    ImGui::PopID();
    return here;
}

std::string DetachedWindows::describe() const {
    std::string text;
    for (const DetachableSectionInfo& section : detachableSections()) {
        const Window& window = state(section.section);
        if (!window.out) continue;
        char entry[128];
        std::snprintf(entry, sizeof entry, "%s@%.0f,%.0f,%.0fx%.0f", section.name, window.position.x, window.position.y,
                      window.size.x, window.size.y);
        text += (text.empty() ? "" : ",") + std::string(entry);
    }
    return text.empty() ? "none" : text;
}

} // namespace ptview
