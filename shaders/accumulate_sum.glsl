// Progressive accumulation into RGBA32F targets. A float sum loses the low bits of each new
// sample once it is large (after 1e5 samples, about 1e-2 relative per add), so the sum is kept
// with Kahan compensation; `precise` stops the compiler from folding the compensation to zero.
// A second-moment sum gives each pixel's own variance for error estimates. The previous sums are
// read here; where the new ones go depends on the entry point (accumulate.glsl for the fragment
// stage, accumulate_image.glsl for compute).

#include "frame_uniforms.glsl"

uniform sampler2D uPrevSum;
uniform sampler2D uPrevCompensation;
uniform sampler2D uPrevSumSquares;

// sampleSum and sampleSquares: the sum of this pass's samples of the pixel, and of their squares.
void accumulatedSums(ivec2 pixel, vec3 sampleSum, vec3 sampleSquares, out vec4 sumOut, out vec4 compensationOut,
                     out vec4 sumSquaresOut) {
    vec3 sum = vec3(0.0);
    vec3 compensation = vec3(0.0);
    vec3 sumSquares = vec3(0.0);
    if (uFrameIndex > 0u) {  // frame 0 starts afresh, so a reset needs no clear
        sum = texelFetch(uPrevSum, pixel, 0).rgb;
        compensation = texelFetch(uPrevCompensation, pixel, 0).rgb;
        sumSquares = texelFetch(uPrevSumSquares, pixel, 0).rgb;
    }
    precise vec3 corrected = sampleSum - compensation;
    precise vec3 newSum = sum + corrected;
    precise vec3 newCompensation = (newSum - sum) - corrected;
    sumOut = vec4(newSum, 1.0);
    compensationOut = vec4(newCompensation, 1.0);
    sumSquaresOut = vec4(sumSquares + sampleSquares, 1.0);
}
