// Smooth dielectrics: specular transmission and glass. Both delta: f and pdf are 0 for any given
// direction; only sampling finds their one or two directions.
#include "bsdf_common.glsl"
#include "material.glsl"
#include "fresnel.glsl"

// Always refracts (no Fresnel reflection). Under total internal reflection nothing is
// transmitted and the sample fails.
BsdfSample sampleSpecularTransmission(vec3 transmittance, float ior, vec3 woLocal) {
    vec3 wiLocal;
    float etaRelative;
    if (woLocal.z == 0.0 || !refractLocal(woLocal, ior, wiLocal, etaRelative)) return failedBsdfSample();
    return BsdfSample(wiLocal, transmittance, 1.0, true);
}

// Smooth dielectric: reflects with the exact Fresnel probability R, refracts otherwise, from
// either side; total internal reflection gives R = 1. Choosing the lobe by R makes the weight
// exactly the tint for both lobes.
BsdfSample sampleGlass(vec3 tint, float ior, vec3 woLocal, float uLobe) {
    if (woLocal.z == 0.0) return failedBsdfSample();
    float reflectance = fresnelDielectric(woLocal.z, ior);
    if (uLobe < reflectance) return BsdfSample(reflectLocal(woLocal), tint, reflectance, true);
    vec3 wiLocal;
    float etaRelative;
    // reflectance < 1 here, so refraction exists; the check guards rounding at the critical angle.
    if (!refractLocal(woLocal, ior, wiLocal, etaRelative)) return BsdfSample(reflectLocal(woLocal), tint, 1.0, true);
    return BsdfSample(wiLocal, tint, 1.0 - reflectance, true);
}

// ---- Entry points of the generated dispatch (bsdf.glsl, renderer/gpu/ShaderFeatures.cpp names
// them NAMEBsdfF / NAMEBsdfPdf / NAMEBsdfSample): what the model reads of a Material, said once.
BsdfSample specularTransmissionBsdfSample(Material material, vec3 woLocal, float uLobe, vec2 u) { return sampleSpecularTransmission(material.color, material.ior, woLocal); }
BsdfSample glassBsdfSample(Material material, vec3 woLocal, float uLobe, vec2 u) { return sampleGlass(material.color, material.ior, woLocal, uLobe); }
