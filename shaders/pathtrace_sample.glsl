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
        accumulateSamples(ivec2(pixel), vec3(0.0), vec3(0.0), 0u, 0u);
        return;
    }
    vec3 sum = vec3(0.0);
    vec3 sumSquares = vec3(0.0);
    Sampler sampler;
    uint sampleIndex = accumulatedSampleCount(ivec2(pixel));
    uint endIndex = sampleIndex + uSamplesPerPass;
    uint edgeRays = 0u;
    // kDebugView is a constant of the program: the branch not taken is compiled out.
    if (kDebugView != kDebugViewRadiance) {
        for (; sampleIndex < endIndex; ++sampleIndex) {
            vec3 value = debugViewValue(generatePixelRay(pixel, sampleIndex, sampler), kDebugView);
            sum += value;
            sumSquares += value * value;
        }
    } else {
        edgeRays = pixelEdgeRays(pixel);
        float cameraWeight = cameraEmissionWeight(edgeRays);
        // A sample on an emission edge is its path and then its edgeRays edge rays, each
        // a path that ends at its first surface (emission_edges.glsl), traced by the same loop:
        // a loop of their own would run once, masked, for every SIMD group, edge or not.
        // The samplers of the two kinds of path, numbered per path below: created once, since
        // the loop runs each line for the whole SIMD group whichever kind its pixels start.
        Sampler pathSampler = createSampler(pixel, sampleIndex, uSeed, kSamplerMode, uSampleBudget);
        Sampler edgeRaySampler = createEdgeRaySampler(pixel, 0u, max(edgeRays, 1u));
        uint edgeRaysLeft = edgeRays;
        vec3 sampleValue = vec3(0.0);
        sampler = pathSampler;
        PathState path = startPath(generatePixelRay(pixel, sampler), cameraWeight, false);
        for (;;) {
            if (extendPath(path, sampler)) continue;
            sampleValue += path.radiance;
            bool edgeRay = edgeRaysLeft > 0u;
            if (edgeRay) {
                --edgeRaysLeft;
            } else {
                sum += sampleValue;
                sumSquares += sampleValue * sampleValue;
                sampleValue = vec3(0.0);
                if (++sampleIndex == endIndex) break;
                edgeRaysLeft = edgeRays;
            }
            sampler = edgeRay ? edgeRaySampler : pathSampler;
            sampler.sampleIndex = edgeRay ? edgeRayIndex(sampleIndex, edgeRays - 1u - edgeRaysLeft, edgeRays) : sampleIndex;
            path = startPath(generatePixelRay(pixel, sampler), cameraWeight, edgeRay);
        }
    }
    accumulateSamples(ivec2(pixel), sum, sumSquares, uSamplesPerPass, edgeRays);
}
