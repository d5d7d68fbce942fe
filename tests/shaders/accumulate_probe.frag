#version 410 core
// Feeds accumulate.glsl a deterministic sequence whose exact mean is known: nine small values and
// one large one per cycle of ten, all exactly representable in float. A plain float sum of it
// drifts by ~5e-4 relative after 1e5 frames, because the small values fall below the sum's ulp.
#include "frame_uniforms.glsl"
#include "accumulate.glsl"

void main() {
    uint k = uFrameIndex % 10u;
    float value = k == 9u ? 10000.0 : 0.125 * float(k) + 0.0625;
    vec3 sampleValue = vec3(value, 0.5 * value, value + 1.0);
    accumulateSamples(ivec2(gl_FragCoord.xy), sampleValue, sampleValue * sampleValue, 1u, 0u);
}
