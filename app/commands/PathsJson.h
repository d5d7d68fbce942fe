#pragma once
// The JSON form of the paths behind a pixel (docs/output.md has the schema): what `ptview paths
// --out` writes and the viewer's `save-paths` too, so a handout and a demo give the same file.

#include <ptview/tracer/RecordedPath.h>
#include <ptview/settings/RenderSettings.h>
#include <ptview/scene/Scene.h>

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace ptview {

struct PathsReport {
    std::string scenePath;
    const Scene* scene = nullptr;  // material names
    RenderSettings settings;       // integrator, sampler, depth, seed, light-path view, budget, clamp
    glm::ivec2 imageSize{0, 0};
    glm::ivec2 pixel{0, 0};        // x from the left, y from the top
    int firstSample = 0;
    const std::vector<RecordedPath>* paths = nullptr;
};

// Whether the scene has media, so that its paths' vertices show the transmittance on the way
// (segment, so far, shadow ray): paths of scenes without media show the fields they always had.
bool pathsShowMedia(const Scene& scene);

// How a recorded path ended: "escaped", "roulette", "emitter", "last_bounce" (the integrator's
// depth: uMaxDepth, or 1 for direct and mis), "direct_only" (the direct integrator stops after
// the first light sample) or "absorbed" (the BSDF sample failed or carried nothing).
const char* pathEnd(const RecordedPath& path, const RenderSettings& settings, const Scene& scene);

std::string pathsToJson(const PathsReport& report);

} // namespace ptview
