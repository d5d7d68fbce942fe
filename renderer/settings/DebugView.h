#pragma once
// What the path-tracing program writes per sample: the radiance, or, to look at the scene's data,
// the first hit's shading normal or albedo (accumulated like samples, so edges are antialiased).

#include <cstdint>
#include <vector>

namespace ptview {

// Values match kDebugView in shaders/debug_view.glsl.
enum class DebugView : std::uint32_t { Radiance = 0, Normals = 1, Albedo = 2 };

struct DebugViewName {
    DebugView view;
    const char* name;
};

inline const std::vector<DebugViewName>& debugViewNames() {
    static const std::vector<DebugViewName> names = {
        {DebugView::Radiance, "radiance"}, {DebugView::Normals, "normals"}, {DebugView::Albedo, "albedo"}};
    return names;
}

inline const char* debugViewName(DebugView view) {
    for (const DebugViewName& entry : debugViewNames())
        if (entry.view == view) return entry.name;
    return "?";
}

} // namespace ptview
