// Rough metal: GGX microfacet reflection with height-correlated Smith shadowing-masking and a
// Schlick Fresnel from the per-channel reflectance at normal incidence; an effectively smooth
// metal is a Fresnel-weighted mirror (delta). Two-sided: evaluated as if wo were on the front
// side (an isotropic BSDF is symmetric under flipping both z's).
#include "bsdf_common.glsl"
#include "material.glsl"
#include "fresnel.glsl"
#include "microfacet.glsl"

vec3 metalF(vec3 reflectance, float roughness, vec3 woLocal, vec3 wiLocal) {
    float alpha = ggxAlpha(roughness);
    if (!sameHemisphere(woLocal, wiLocal) || ggxIsEffectivelySmooth(alpha)) return vec3(0.0);
    float side = frontSide(woLocal);
    vec3 wo = flipToSide(woLocal, side);
    vec3 wi = flipToSide(wiLocal, side);
    vec3 h = wo + wi;
    if (dot(h, h) == 0.0) return vec3(0.0);
    h = normalize(h);
    return fresnelSchlick(reflectance, dot(wo, h)) * ggxD(h, alpha) * ggxG2(wo, wi, alpha) / (4.0 * wo.z * wi.z);
}

float metalPdf(float roughness, vec3 woLocal, vec3 wiLocal) {
    if (!sameHemisphere(woLocal, wiLocal) || ggxIsEffectivelySmooth(ggxAlpha(roughness))) return 0.0;
    float side = frontSide(woLocal);
    return ggxReflectionPdf(flipToSide(woLocal, side), flipToSide(wiLocal, side), ggxAlpha(roughness));
}

BsdfSample sampleMetal(vec3 reflectance, float roughness, vec3 woLocal, vec2 u) {
    if (woLocal.z == 0.0) return failedBsdfSample();
    float side = frontSide(woLocal);
    vec3 wo = flipToSide(woLocal, side);
    float alpha = ggxAlpha(roughness);
    if (ggxIsEffectivelySmooth(alpha))
        return BsdfSample(reflectLocal(woLocal), fresnelSchlick(reflectance, wo.z), 1.0, true);
    vec3 h = sampleGgxVisibleNormal(wo, alpha, u);
    vec3 wi = reflect(-wo, h);
    float woDotH = dot(wo, h);
    if (wi.z <= 0.0 || woDotH <= 0.0) return failedBsdfSample();
    // f cos / pdf with pdf = G1(wo) D (wo.h) / (wo.z 4 (wo.h)): D and the cosines cancel.
    vec3 weight = fresnelSchlick(reflectance, woDotH) * (ggxG2(wo, wi, alpha) / ggxG1(wo, alpha));
    float pdf = ggxVisibleNormalPdf(wo, h, alpha) / (4.0 * woDotH);
    return BsdfSample(flipToSide(wi, side), weight, pdf, false);
}

// ---- Entry points of the generated dispatch (bsdf.glsl, renderer/gpu/ShaderFeatures.cpp names
// them NAMEBsdfF / NAMEBsdfPdf / NAMEBsdfSample): what the model reads of a Material, said once.
vec3 metalBsdfF(Material material, vec3 woLocal, vec3 wiLocal) { return metalF(material.color, material.roughness, woLocal, wiLocal); }
float metalBsdfPdf(Material material, vec3 woLocal, vec3 wiLocal) { return metalPdf(material.roughness, woLocal, wiLocal); }
BsdfSample metalBsdfSample(Material material, vec3 woLocal, float uLobe, vec2 u) { return sampleMetal(material.color, material.roughness, woLocal, u); }
