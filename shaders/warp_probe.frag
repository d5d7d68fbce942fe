#version 410 core
// Runs the product's sampler and warps on a grid of fragments and writes what they produce, for
// the statistical tests and the warp visualizer (renderer/probes/WarpProbe.cpp).
//
// uProbeMode 0 (warp): fragment i draws sample i % uSamplesPerPixel of "pixel" i / uSamplesPerPixel
//   from the sampler, warps it, and writes (point.xyz, pdf(point)) and (u.xy, inverse(point).xy).
// uProbeMode 1 (pdf): fragment i reads point i from uPoints and writes (pdf(point), 0, 0, 0).
#include "sampler.glsl"
#include "warps.glsl"
#include "warp_ids.glsl"

uniform int uProbeMode;
uniform int uWarp;
uniform float uCosThetaMax;     // uniform cone only
uniform float uG;               // henyey-greenstein only
uniform int uWidth;             // fragments per row
uniform int uCount;             // fragments that carry work
uniform uint uSamplerMode;
uniform uint uSampleBudget;
uniform uint uSamplesPerPixel;
uniform uint uSeed;
uniform uint uDimension;
uniform sampler2D uPoints;      // pdf mode: one point per texel, same layout as the output

layout(location = 0) out vec4 outPointAndPdf;
layout(location = 1) out vec4 outUAndInverse;

vec3 warpPoint(vec2 u) {
    if (uWarp == kWarpUniformDiskPolar) return vec3(sampleUniformDiskPolar(u), 0.0);
    if (uWarp == kWarpUniformDiskConcentric) return vec3(sampleUniformDiskConcentric(u), 0.0);
    if (uWarp == kWarpUniformSphere) return sampleUniformSphere(u);
    if (uWarp == kWarpUniformCone) return sampleUniformCone(u, uCosThetaMax);
    if (uWarp == kWarpUniformHemisphere) return sampleUniformHemisphere(u);
    if (uWarp == kWarpCosineHemisphere) return sampleCosineHemisphere(u);
    if (uWarp == kWarpUniformTriangle) return vec3(sampleUniformTriangle(u), 0.0);
    if (uWarp == kWarpHenyeyGreenstein) return sampleHenyeyGreenstein(u, uG);
    return vec3(u, 0.0);
}

float warpPdf(vec3 p) {
    if (uWarp == kWarpUniformDiskPolar || uWarp == kWarpUniformDiskConcentric) return uniformDiskPdf(p.xy);
    if (uWarp == kWarpUniformSphere) return uniformSpherePdf(p);
    if (uWarp == kWarpUniformCone) return uniformConePdf(p, uCosThetaMax);
    if (uWarp == kWarpUniformHemisphere) return uniformHemispherePdf(p);
    if (uWarp == kWarpCosineHemisphere) return cosineHemispherePdf(p.z);
    if (uWarp == kWarpUniformTriangle) return uniformTrianglePdf(p.xy);
    if (uWarp == kWarpHenyeyGreenstein) return henyeyGreensteinPdf(p.z, uG);
    return all(greaterThanEqual(p.xy, vec2(0.0))) && all(lessThan(p.xy, vec2(1.0))) ? 1.0 : 0.0;
}

vec2 invertWarp(vec3 p) {
    if (uWarp == kWarpUniformDiskPolar) return invertUniformDiskPolar(p.xy);
    if (uWarp == kWarpUniformDiskConcentric) return invertUniformDiskConcentric(p.xy);
    if (uWarp == kWarpUniformSphere) return invertUniformSphere(p);
    if (uWarp == kWarpUniformCone) return invertUniformCone(p, uCosThetaMax);
    if (uWarp == kWarpUniformHemisphere) return invertUniformHemisphere(p);
    if (uWarp == kWarpCosineHemisphere) return invertCosineHemisphere(p);
    if (uWarp == kWarpUniformTriangle) return invertUniformTriangle(p.xy);
    if (uWarp == kWarpHenyeyGreenstein) return invertHenyeyGreenstein(p, uG);
    return p.xy;
}

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    int index = texel.y * uWidth + texel.x;
    outPointAndPdf = vec4(0.0);
    outUAndInverse = vec4(0.0);
    if (index >= uCount) return;

    if (uProbeMode == 1) {
        outPointAndPdf = vec4(warpPdf(texelFetch(uPoints, texel, 0).xyz), 0.0, 0.0, 0.0);
        return;
    }
    uint sampleIndex = uint(index) % uSamplesPerPixel;
    uint pixel = uint(index) / uSamplesPerPixel;
    Sampler sampler = createSampler(uvec2(pixel, 0u), sampleIndex, uSeed, uSamplerMode, uSampleBudget);
    vec2 u = samplerGet2D(sampler, uDimension);
    vec3 point = warpPoint(u);
    outPointAndPdf = vec4(point, warpPdf(point));
    outUAndInverse = vec4(u, invertWarp(point));
}
