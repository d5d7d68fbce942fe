#pragma once
// What the path-tracing program writes per sample: the radiance, or, to look at the scene's data,
// the first hit's shading normal, albedo or distance from the camera (accumulated like samples, so
// edges are antialiased). The EXR AOVs of `ptview render --aovs` are these views.

#include <ptview/settings/EnumTable.h>

#include <cstdint>

namespace ptview {

enum class DebugView : std::uint32_t { Radiance = 0, Normals = 1, Albedo = 2, Depth = 3 };

inline const EnumTable<DebugView>& debugViewNames() {
    static const EnumTable<DebugView> table = {
        {DebugView::Radiance, "radiance", nullptr, "", "kDebugViewRadiance"},
        {DebugView::Normals, "normals", nullptr, "", "kDebugViewNormals"},
        {DebugView::Albedo, "albedo", nullptr, "", "kDebugViewAlbedo"},
        {DebugView::Depth, "depth", nullptr, "", "kDebugViewDepth"},
    };
    return table;
}

inline const char* debugViewName(DebugView view) { return debugViewNames().name(view); }

} // namespace ptview
