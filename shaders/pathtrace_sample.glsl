// A pass's path samples for one pixel, added to its accumulation: the work both entry points
// (pathtrace.frag, pathtrace.comp) do per pixel. They include their own accumulate*.glsl first.
#include "frame_uniforms.glsl"
#include "constants.glsl"
#include "sampler.glsl"
#include "camera.glsl"
#include "integrator.glsl"
#include "specialization.glsl"
#include "debug_view.glsl"

// uSamplesPerPass samples, numbered on from the pixel's own count (uFrameIndex unless adaptive
// sampling stopped the pixel, and then it takes none: accumulate_sum.glsl). One loop extends
// whichever path a pixel is on and starts the pixel's next sample as soon as one ends. The pixels of a SIMD group (8 on
// llvmpipe's AVX2, 32 on a GPU warp) run the loop together until the last of them is done, so
// nesting a loop over bounces inside one over samples would keep each group waiting for its
// longest path at every sample; this way a group waits once, for its longest total.
void traceSamples(uvec2 pixel) {
    if (!pixelTakesSamples(ivec2(pixel))) {
        accumulateSamples(ivec2(pixel), vec3(0.0), vec3(0.0), 0u);
        return;
    }
    vec3 sum = vec3(0.0);
    vec3 sumSquares = vec3(0.0);
    Sampler sampler;
    uint sampleIndex = accumulatedSampleCount(ivec2(pixel));
    uint endIndex = sampleIndex + uSamplesPerPass;
    // kDebugView is a constant of the program: the branch not taken is compiled out.
    if (kDebugView != kDebugViewRadiance) {
        for (; sampleIndex < endIndex; ++sampleIndex) {
            vec3 value = debugViewValue(generatePixelRay(pixel, sampleIndex, sampler), kDebugView);
            sum += value;
            sumSquares += value * value;
        }
    } else {
        PathState path = startPath(generatePixelRay(pixel, sampleIndex, sampler));
        for (;;) {
            if (extendPath(path, sampler)) continue;
            sum += path.radiance;
            sumSquares += path.radiance * path.radiance;
            if (++sampleIndex == endIndex) break;
            path = startPath(generatePixelRay(pixel, sampleIndex, sampler));
        }
    }
    accumulateSamples(ivec2(pixel), sum, sumSquares, uSamplesPerPass);
}
