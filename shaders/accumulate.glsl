// Accumulation from the fragment stage: the new sums go to the three draw buffers.
#include "accumulate_sum.glsl"

layout(location = 0) out vec4 outSum;
layout(location = 1) out vec4 outCompensation;
layout(location = 2) out vec4 outSumSquares;

void accumulateSamples(ivec2 pixel, vec3 sampleSum, vec3 sampleSquares, uint samplesAdded, uint edgeRays) {
    accumulatedSums(pixel, sampleSum, sampleSquares, samplesAdded, edgeRays, outSum, outCompensation, outSumSquares);
}
