// Progressive accumulation into RGBA32F targets. A float sum loses the low bits of each new
// sample once it is large (after 1e5 samples, about 1e-2 relative per add), so the sum is kept
// with Kahan compensation; `precise` stops the compiler from folding the compensation to zero.
// A second-moment sum gives each pixel's own variance for error estimates. The previous sums are
// read here; where the new ones go depends on the entry point (accumulate.glsl for the fragment
// stage, accumulate_image.glsl for compute).
//
// The alpha channels hold the per-pixel state adaptive sampling needs (docs/sampling.md), beside
// the sums it describes: the sum's alpha counts the pixel's own samples (exact in a float up to
// 2^24), so a pixel that stopped early keeps its own mean; the sum of squares' alpha is 1 while
// the pixel takes samples and 0 once adaptive sampling stopped it (Accumulator::stopPixels writes
// it). OpenGL 4.1 guarantees 16 texture units and the path tracer uses all of them, so the mask
// has no texture of its own. Without adaptive sampling every count is uFrameIndex and every
// pixel takes samples. The compensation's alpha is the number of edge rays a sample of the pixel
// takes, 0 unless it straddles an emission edge (emission_edges.glsl), decided with its first
// samples and kept from then on.

#include "frame_uniforms.glsl"

uniform sampler2D uPrevSum;
uniform sampler2D uPrevCompensation;
uniform sampler2D uPrevSumSquares;

// Samples the pixel has accumulated: its next sample's index (each pixel numbers its own 0, 1, 2, ...).
uint accumulatedSampleCount(ivec2 pixel) {
    return uFrameIndex > 0u ? uint(texelFetch(uPrevSum, pixel, 0).a) : 0u;
}

// The edge rays the pixel's first samples chose (emission_edges.glsl): 0 off an emission edge.
uint storedEdgeRays(ivec2 pixel) {
    return uint(texelFetch(uPrevCompensation, pixel, 0).a + 0.5);
}

// False once adaptive sampling stopped the pixel: it then adds no samples.
bool pixelTakesSamples(ivec2 pixel) {
    return uFrameIndex == 0u || texelFetch(uPrevSumSquares, pixel, 0).a > 0.0;
}

// sampleSum and sampleSquares: the sum of this pass's samplesAdded samples of the pixel, and of
// their squares; edgeRays: what the pixel's next passes read from storedEdgeRays.
void accumulatedSums(ivec2 pixel, vec3 sampleSum, vec3 sampleSquares, uint samplesAdded, uint edgeRays,
                     out vec4 sumOut, out vec4 compensationOut, out vec4 sumSquaresOut) {
    vec4 sum = vec4(0.0);
    vec4 compensation = vec4(0.0);
    vec4 sumSquares = vec4(0.0, 0.0, 0.0, 1.0); // takes samples
    if (uFrameIndex > 0u) {  // frame 0 starts afresh, so a reset needs no clear
        sum = texelFetch(uPrevSum, pixel, 0);
        compensation = texelFetch(uPrevCompensation, pixel, 0);
        sumSquares = texelFetch(uPrevSumSquares, pixel, 0);
    }
    if (samplesAdded == 0u) { // a stopped pixel keeps its sums bit for bit
        sumOut = sum;
        compensationOut = compensation;
        sumSquaresOut = sumSquares;
        return;
    }
    precise vec3 corrected = sampleSum - compensation.rgb;
    precise vec3 newSum = sum.rgb + corrected;
    precise vec3 newCompensation = (newSum - sum.rgb) - corrected;
    sumOut = vec4(newSum, sum.a + float(samplesAdded));
    compensationOut = vec4(newCompensation, float(edgeRays));
    sumSquaresOut = vec4(sumSquares.rgb + sampleSquares, sumSquares.a);
}
