#version 410 core
// Runs the product's light sampling (shaders/lights.glsl) once per texel of a ProbePass grid, for
// tests/LightSamplingTest.cpp. Input 0: (shading point, -); input 1: uProbeMode 0: (u.xy, -, -),
// uProbeMode 1: (direction toward the light, distance to it). uLightNormal: the light's geometric
// normal where the direction meets it (what the integrator passes to lightPdf).
//   mode 0 (sample): out0 = (wi, pdfSolidAngle), out1 = (distance, lightPdf(wi) at the sampled
//                    point, radiance.r, isDelta);
//   mode 1 (pdf):    out0 = (lightPdf(direction), 0, 0, 0).
#include "lights.glsl"

uniform int uWidth; // fragments per row
uniform int uCount; // fragments that carry work
uniform int uProbeMode;
uniform int uLight;
uniform vec3 uLightNormal;
uniform sampler2D uInput0;
uniform sampler2D uInput1;

layout(location = 0) out vec4 out0;
layout(location = 1) out vec4 out1;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    out0 = vec4(0.0);
    out1 = vec4(0.0);
    if (texel.y * uWidth + texel.x >= uCount) return;
    vec3 posWorld = texelFetch(uInput0, texel, 0).xyz;
    vec4 in1 = texelFetch(uInput1, texel, 0);
    if (uProbeMode == 1) {
        out0.x = lightPdf(uLight, posWorld, in1.xyz, in1.w, uLightNormal);
        return;
    }
    LightSample ls = sampleLight(uLight, posWorld, in1.xy);
    out0 = vec4(ls.wi, ls.pdfSolidAngle);
    out1 = vec4(ls.distance, lightPdf(uLight, posWorld, ls.wi, ls.distance, uLightNormal), ls.radiance.r,
                ls.isDelta ? 1.0 : 0.0);
}
