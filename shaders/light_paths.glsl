// The light-path explorer (renderer/settings/LightPaths.h): which of a path's contributions an
// image adds up. A contribution's bounces k are the scattering vertices between the camera and
// the light. The paths are traced as always; only what is added changes, so the exactly-k images
// over k add up to the full image sample for sample. Compiled only into programs that show a
// part of the light; light_paths_none.glsl takes its place otherwise.
#include "frame_uniforms.glsl"
#include "specialization.glsl"

// What a caustic needs to know of the vertices so far, from the camera: how many scattered by a
// non-delta lobe, and how many delta (mirror, glass) vertices followed the last of those.
struct PathHistory {
    int nonDeltaVertices;
    int deltaVerticesAfterNonDelta;
};

PathHistory startPathHistory() { return PathHistory(0, 0); }

void recordScattering(inout PathHistory history, bool deltaLobe) {
    if (!deltaLobe) {
        history.nonDeltaVertices += 1;
        history.deltaVerticesAfterNonDelta = 0;
    } else if (history.nonDeltaVertices > 0) {
        history.deltaVerticesAfterNonDelta += 1;
    }
}

// 1 where a contribution of a path of `bounces` scattering vertices belongs to this view, else 0.
// foundByBsdfSample: emission the path ran into (as opposed to a light sample's shadow ray). A
// caustic, camera - delta* - non-delta - delta+ - light, can only be found that way: no light
// sample passes a mirror or glass.
float lightPathWeight(int bounces, PathHistory history, bool foundByBsdfSample) {
    bool counts = true;
    if (kLightPaths == kLightPathsExactly) counts = bounces == uLightPathBounces;
    else if (kLightPaths == kLightPathsAtMost) counts = bounces <= uLightPathBounces;
    else if (kLightPaths == kLightPathsDirect) counts = bounces <= 1;
    else if (kLightPaths == kLightPathsIndirect) counts = bounces >= 2;
    else if (kLightPaths == kLightPathsCaustics)
        counts = foundByBsdfSample && history.nonDeltaVertices == 1 && history.deltaVerticesAfterNonDelta >= 1;
    return counts ? 1.0 : 0.0;
}
