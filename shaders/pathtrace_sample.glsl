// One path sample for one pixel, added to its accumulation: the work both entry points
// (pathtrace.frag, pathtrace.comp) do per pixel. They include their own accumulate*.glsl first.
#include "frame_uniforms.glsl"
#include "constants.glsl"
#include "sampler.glsl"
#include "camera.glsl"
#include "integrator.glsl"
#include "specialization.glsl"
#include "debug_view.glsl"

void traceSample(ivec2 pixel) {
    Sampler sampler = createSampler(uvec2(pixel), uFrameIndex, uSeed, kSamplerMode, uSampleBudget);
    vec2 filmPos = vec2(pixel) + samplerGet2D(sampler, kDimensionCamera); // box filter one pixel wide
    Ray ray = generateCameraRay(filmPos, sampler);
    // kDebugView is a constant of the program: the branch not taken is compiled out.
    accumulateSample(pixel, kDebugView == kDebugViewRadiance ? estimateRadiance(ray, sampler) : debugViewValue(ray, kDebugView));
}
