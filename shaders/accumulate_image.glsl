// Accumulation from a compute shader: the new sums are stored into the write targets, bound as
// images (OpenGL 4.3).
#include "accumulate_sum.glsl"

layout(rgba32f) uniform writeonly image2D uNextSum;
layout(rgba32f) uniform writeonly image2D uNextCompensation;
layout(rgba32f) uniform writeonly image2D uNextSumSquares;

void accumulateSamples(ivec2 pixel, vec3 sampleSum, vec3 sampleSquares, uint samplesAdded, uint edgeRays) {
    vec4 sum, compensation, sumSquares;
    accumulatedSums(pixel, sampleSum, sampleSquares, samplesAdded, edgeRays, sum, compensation, sumSquares);
    imageStore(uNextSum, pixel, sum);
    imageStore(uNextCompensation, pixel, compensation);
    imageStore(uNextSumSquares, pixel, sumSquares);
}
