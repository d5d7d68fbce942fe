#version 410 core
// Runs the product's BSDFs on a grid of work items and writes what they produce, for the
// statistical tests (renderer/probes/BsdfProbe.cpp). The material is uniform over the pass; each item
// has its own wo (uWo texture, local frame) and, in eval mode, its own wi (uWi texture).
//
// uProbeMode 0 (sample): item i samples the BSDF with sample i of the sampler, then writes
//   (wi, pdf), (weight, isDelta), (f(wo, wi), pdf(wo, wi)) re-evaluated at the sampled wi.
// uProbeMode 1 (eval): writes (f(wo, wi), pdf(wo, wi)).
#include "sampler.glsl"
#include "bsdf.glsl"

uniform int uProbeMode;
uniform int uWidth;
uniform int uCount;
uniform uint uMaterialType;
uniform vec3 uColor;
uniform float uIor;
uniform float uRoughness;
uniform float uMetallic;
uniform float uTransmission;
uniform uint uSamplerMode;
uniform uint uSeed;
uniform sampler2D uWo;
uniform sampler2D uWi;

layout(location = 0) out vec4 outFirst;
layout(location = 1) out vec4 outSecond;
layout(location = 2) out vec4 outThird;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    int index = texel.y * uWidth + texel.x;
    outFirst = vec4(0.0);
    outSecond = vec4(0.0);
    outThird = vec4(0.0);
    if (index >= uCount) return;

    Material material = Material(uMaterialType, uColor, uIor, vec3(0.0), uRoughness, uMetallic, uTransmission);
    vec3 woLocal = texelFetch(uWo, texel, 0).xyz;
    if (uProbeMode == 1) {
        vec3 wiLocal = texelFetch(uWi, texel, 0).xyz;
        outFirst = vec4(bsdfF(material, woLocal, wiLocal), bsdfPdf(material, woLocal, wiLocal));
        return;
    }
    Sampler sampler = createSampler(uvec2(0u), uint(index), uSeed, uSamplerMode, uint(uCount));
    BsdfSample bs = sampleBsdf(material, woLocal, samplerGet1D(sampler, bsdfLobeDimension(0)),
                               samplerGet2D(sampler, bsdfDimension(0)));
    outFirst = vec4(bs.wiLocal, bs.pdfSolidAngle);
    outSecond = vec4(bs.weight, bs.isDelta ? 1.0 : 0.0);
    outThird = vec4(bsdfF(material, woLocal, bs.wiLocal), bsdfPdf(material, woLocal, bs.wiLocal));
}
