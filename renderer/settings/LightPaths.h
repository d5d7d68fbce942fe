#pragma once
// The light-path explorer: which part of the light transport an image shows, for teaching. Every
// contribution a path makes belongs to a path of some number of bounces k (the scattering
// vertices between the camera and the light: 0 for an emitter seen directly, 1 for direct
// lighting, ...), so the views below split the image into parts that add up to it: the
// exactly-k images over k = 0..MAX_DEPTH sum to the full image, direct + indirect = all.
// Only the views change what is added up; the paths traced are the same, sample for sample.

#include <ptview/settings/EnumTable.h>

#include <cstdint>

namespace ptview {

enum class LightPaths : std::uint32_t { All = 0, Exactly = 1, AtMost = 2, Direct = 3, Indirect = 4, Caustics = 5 };

inline const EnumTable<LightPaths>& lightPathsNames() {
    static const EnumTable<LightPaths> table = {
        {LightPaths::All, "all", "All light", "every path: the render", "kLightPathsAll"},
        {LightPaths::Exactly, "exactly", "Exactly k bounces", "only light that arrives after exactly k bounces",
         "kLightPathsExactly"},
        {LightPaths::AtMost, "at-most", "At most k bounces", "only light that arrives after k bounces or fewer",
         "kLightPathsAtMost"},
        {LightPaths::Direct, "direct", "Direct only", "emitters seen directly and light after one bounce (k <= 1)",
         "kLightPathsDirect"},
        {LightPaths::Indirect, "indirect", "Indirect only", "light after two bounces or more (k >= 2)",
         "kLightPathsIndirect"},
        {LightPaths::Caustics, "caustics", "Caustics only",
         "light that reached a diffuse surface through mirrors or glass (camera, delta bounces, one non-delta "
         "bounce, one or more delta bounces, light)",
         "kLightPathsCaustics"},
    };
    return table;
}

inline const char* lightPathsName(LightPaths paths) { return lightPathsNames().name(paths); }

// Whether a view reads the number of bounces k (RenderSettings::lightPathBounces).
inline bool lightPathsUseBounces(LightPaths paths) {
    return paths == LightPaths::Exactly || paths == LightPaths::AtMost;
}

} // namespace ptview
