// Which kinds of light a program samples (lights.glsl sampleLight and lightPdf): here every kind.
// A program built for a scene has only the kinds that scene has instead (renderer/gpu/
// ShaderFeatures.cpp generates this file in its place), and the dispatch compiles out the others:
// llvmpipe runs every branch of a dispatch for each SIMD group, masked, whichever kinds its lanes
// hold, so a kind the scene lacks would cost its sampling code at every bounce.
bool hasLightKind(uint kind) {
    return true;
}

// Whether any surface comes near enough a quad light's front to sample it by solid angle
// (lights.glsl viewQuadLight; renderer/gpu/QuadLightReach.h): here, maybe.
const bool kQuadLightsUpClose = true;
