#version 410 core
// Fragment entry: a full-screen triangle, one fragment per pixel, one sample per pass.
#include "accumulate.glsl"
#include "pathtrace_sample.glsl"

void main() {
    traceSample(ivec2(gl_FragCoord.xy));
}
