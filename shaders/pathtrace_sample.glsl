// A pass's path samples for one pixel, added to its accumulation: the work both entry points
// (pathtrace.frag, pathtrace.comp) do per pixel. They include their own accumulate*.glsl first.
#include "frame_uniforms.glsl"
#include "constants.glsl"
#include "sampler.glsl"
#include "camera.glsl"
#include "integrator.glsl"
#include "emission_edges.glsl"
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
        accumulateSamples(ivec2(pixel), vec3(0.0), vec3(0.0), 0u, false);
        return;
    }
    vec3 sum = vec3(0.0);
    vec3 sumSquares = vec3(0.0);
    Sampler sampler;
    uint sampleIndex = accumulatedSampleCount(ivec2(pixel));
    uint endIndex = sampleIndex + uSamplesPerPass;
    bool onEmissionEdge = false;
    // kDebugView is a constant of the program: the branch not taken is compiled out.
    if (kDebugView != kDebugViewRadiance) {
        for (; sampleIndex < endIndex; ++sampleIndex) {
            vec3 value = debugViewValue(generatePixelRay(pixel, sampleIndex, sampler), kDebugView);
            sum += value;
            sumSquares += value * value;
        }
    } else {
        onEmissionEdge = pixelOnEmissionEdge(pixel);
        float cameraWeight = cameraEmissionWeight(onEmissionEdge);
        vec3 edgeSum, edgeSumSquares; // a program without edge rays folds them to 0 (edgeRaysPay)
        traceEdgeRays(pixel, sampleIndex, onEmissionEdge ? uSamplesPerPass : 0u, edgeSum, edgeSumSquares);
        PathState path = startPath(generatePixelRay(pixel, sampleIndex, sampler), cameraWeight);
        for (;;) {
            if (extendPath(path, sampler)) continue;
            sum += path.radiance;
            sumSquares += path.radiance * path.radiance;
            if (++sampleIndex == endIndex) break;
            path = startPath(generatePixelRay(pixel, sampleIndex, sampler), cameraWeight);
        }
        // A sample is its path plus its edge rays, whose random numbers are apart: the cross term
        // of the squares, 2 x (a path) x (its edge rays), is taken as the pass's paths times its
        // edge rays over the samples, as for independent samples. Unbiased, but where passes end
        // changes it: on emission edges a pass of 16 samples reports not quite the variance 16
        // passes of one do (PathTracer.SeveralSamplesPerPassAreTheSamplesOfSinglePasses).
        sumSquares += edgeSumSquares + 2.0 * sum * edgeSum / float(uSamplesPerPass);
        sum += edgeSum;
    }
    accumulateSamples(ivec2(pixel), sum, sumSquares, uSamplesPerPass, onEmissionEdge);
}
