// The kinds of light this program samples (lights.glsl sampleLight and lightPdf): quad, sphere, disk, environment, point, spot, triangle, directional.
// Generated for each program by generateLightKinds (renderer/gpu/ShaderFeatures.cpp) from the
// kinds its scene has, and the dispatch compiles out the others: llvmpipe runs every branch of a
// dispatch for each SIMD group, masked, so a kind the scene lacks would cost its sampling code at
// every bounce. shaders/light_kinds.glsl is the output for every kind, as unspecialized test
// programs compile it.
#include "enums.glsl"

bool hasLightKind(uint kind) {
    return kind == kLightQuad || kind == kLightSphere || kind == kLightDisk || kind == kLightEnvironment || kind == kLightPoint || kind == kLightSpot || kind == kLightTriangle || kind == kLightDirectional;
}

// Whether any surface comes near enough a quad light's front to sample it by solid angle
// (lights.glsl viewQuadLight; renderer/gpudata/QuadLightReach.h).
const bool kQuadLightsUpClose = true;
