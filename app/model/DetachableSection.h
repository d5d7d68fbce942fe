#pragma once
// The sections of the viewer's sidebar that can be popped out into their own window
// (app/window/DetachedWindows.h): one table for the window, the script parser (`pop-out NAME
// on|off`) and the status line.

#include <array>
#include <cstddef>

namespace ptview {

enum class DetachableSection { PathsTable, LightPaths, Compare };

struct DetachableSectionInfo {
    DetachableSection section;
    const char* name;  // in scripts and the status line
    const char* title; // the window's title
};

inline const std::array<DetachableSectionInfo, 3>& detachableSections() {
    static const std::array<DetachableSectionInfo, 3> sections = {{
        {DetachableSection::PathsTable, "paths-table", "Paths behind the pixel"},
        {DetachableSection::LightPaths, "light-paths", "Views and light paths"},
        {DetachableSection::Compare, "compare", "Split view"},
    }};
    return sections;
}

inline const DetachableSectionInfo& detachableSectionInfo(DetachableSection section) {
    return detachableSections()[static_cast<std::size_t>(section)];
}

} // namespace ptview
