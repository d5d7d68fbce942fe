// Lambertian reflection and transmission.
#include "bsdf_common.glsl"
#include "material.glsl"
#include "warps.glsl"

// Reflection, two-sided: light leaves on wo's side.
vec3 lambertianReflectionF(vec3 albedo, vec3 woLocal, vec3 wiLocal) {
    return sameHemisphere(woLocal, wiLocal) ? albedo * kInvPi : vec3(0.0);
}

float lambertianReflectionPdf(vec3 woLocal, vec3 wiLocal) {
    return sameHemisphere(woLocal, wiLocal) ? cosineHemispherePdf(absCosTheta(wiLocal)) : 0.0;
}

BsdfSample sampleLambertianReflection(vec3 albedo, vec3 woLocal, vec2 u) {
    if (woLocal.z == 0.0) return failedBsdfSample();
    vec3 wiLocal = sampleCosineHemisphere(u);
    wiLocal.z = woLocal.z < 0.0 ? -wiLocal.z : wiLocal.z;
    float pdf = lambertianReflectionPdf(woLocal, wiLocal);
    if (pdf == 0.0) return failedBsdfSample();
    return BsdfSample(wiLocal, albedo, pdf, false); // albedo/pi * cos / (cos/pi)
}

// Transmission: light leaves on the side opposite wo.
vec3 lambertianTransmissionF(vec3 transmittance, vec3 woLocal, vec3 wiLocal) {
    return woLocal.z * wiLocal.z < 0.0 ? transmittance * kInvPi : vec3(0.0);
}

float lambertianTransmissionPdf(vec3 woLocal, vec3 wiLocal) {
    return woLocal.z * wiLocal.z < 0.0 ? cosineHemispherePdf(absCosTheta(wiLocal)) : 0.0;
}

BsdfSample sampleLambertianTransmission(vec3 transmittance, vec3 woLocal, vec2 u) {
    if (woLocal.z == 0.0) return failedBsdfSample();
    vec3 wiLocal = sampleCosineHemisphere(u);
    wiLocal.z = woLocal.z > 0.0 ? -wiLocal.z : wiLocal.z;
    float pdf = lambertianTransmissionPdf(woLocal, wiLocal);
    if (pdf == 0.0) return failedBsdfSample();
    return BsdfSample(wiLocal, transmittance, pdf, false);
}

// ---- Entry points of the generated dispatch (bsdf.glsl, renderer/gpu/ShaderFeatures.cpp names
// them NAMEBsdfF / NAMEBsdfPdf / NAMEBsdfSample): what the model reads of a Material, said once.
vec3 lambertianReflectionBsdfF(Material material, vec3 woLocal, vec3 wiLocal) { return lambertianReflectionF(material.color, woLocal, wiLocal); }
float lambertianReflectionBsdfPdf(Material material, vec3 woLocal, vec3 wiLocal) { return lambertianReflectionPdf(woLocal, wiLocal); }
BsdfSample lambertianReflectionBsdfSample(Material material, vec3 woLocal, float uLobe, vec2 u) { return sampleLambertianReflection(material.color, woLocal, u); }
vec3 lambertianTransmissionBsdfF(Material material, vec3 woLocal, vec3 wiLocal) { return lambertianTransmissionF(material.color, woLocal, wiLocal); }
float lambertianTransmissionBsdfPdf(Material material, vec3 woLocal, vec3 wiLocal) { return lambertianTransmissionPdf(woLocal, wiLocal); }
BsdfSample lambertianTransmissionBsdfSample(Material material, vec3 woLocal, float uLobe, vec2 u) { return sampleLambertianTransmission(material.color, woLocal, u); }
