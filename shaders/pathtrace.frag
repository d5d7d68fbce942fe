#version 410 core
// One sample per pixel per pass: trace a camera path, add its radiance to the accumulation.
#include "frame_uniforms.glsl"
#include "constants.glsl"
#include "sampler.glsl"
#include "camera.glsl"
#include "integrator.glsl"
#include "accumulate.glsl"

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    Sampler sampler = createSampler(uvec2(pixel), uFrameIndex, uSeed, uSamplerMode, uSampleBudget);
    vec2 filmPos = vec2(pixel) + samplerGet2D(sampler, kDimensionCamera); // box filter one pixel wide
    accumulateSample(pixel, estimateRadiance(generateCameraRay(filmPos), sampler));
}
