#version 410 core
// Runs the product's environment-map functions (shaders/environment_map.glsl) once per texel of a
// ProbePass grid, for tests/EnvironmentMapTest.cpp. Input texture 0 holds one item per texel.
//
// uProbeMode 0 (sample): item = (u.x, u.y, -, -). Writes
//   out0 = (sampleEnvironmentMap(u) direction, its pdfSolidAngle),
//   out1 = (the sampled map coordinates (u, v), environmentMapPdf(direction), pdfUv),
//   out2 = (environmentMapRadiance(direction), 0).
// uProbeMode 1 (evaluate): item = (direction, -). Writes
//   out0 = (environmentMapPdf(direction), environmentMapUv(direction), 0),
//   out1 = (environmentMapRadiance(direction), 0), out2 = 0.
#include "environment_map.glsl"

uniform int uProbeMode;
uniform int uWidth; // fragments per row
uniform int uCount; // fragments that carry work
uniform sampler2D uItems;

layout(location = 0) out vec4 out0;
layout(location = 1) out vec4 out1;
layout(location = 2) out vec4 out2;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    out0 = vec4(0.0);
    out1 = vec4(0.0);
    out2 = vec4(0.0);
    if (texel.y * uWidth + texel.x >= uCount) return;
    vec4 item = texelFetch(uItems, texel, 0);
    if (uProbeMode == 0) {
        float pdfSolidAngle;
        vec3 direction = sampleEnvironmentMap(item.xy, pdfSolidAngle);
        float pdfUv;
        vec2 uv = sampleEnvironmentMapUv(item.xy, pdfUv);
        out0 = vec4(direction, pdfSolidAngle);
        out1 = vec4(uv, environmentMapPdf(direction), pdfUv);
        out2 = vec4(environmentMapRadiance(direction), 0.0);
    } else {
        out0 = vec4(environmentMapPdf(item.xyz), environmentMapUv(item.xyz), 0.0);
        out1 = vec4(environmentMapRadiance(item.xyz), 0.0);
    }
}
