#version 410 core
// Fragment entry: a full-screen triangle, one fragment per pixel, uSamplesPerPass samples per pass.
#include "accumulate.glsl"
#include "pathtrace_sample.glsl"

void main() {
    traceSamples(uvec2(gl_FragCoord.xy));
}
