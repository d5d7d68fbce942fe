// BSDFs.
//
// Conventions (all BSDF code follows them):
// - Directions point away from the surface: wo toward the viewer (the previous path vertex),
//   wi toward the light (the next vertex). Suffix Local = in the shading frame, where +z is the
//   shading normal turned to the side of wo.
// - f(wo, wi) is the BSDF value alone; it does NOT include |cos(theta_i)|.
// - A sample's weight is f(wo, wi) * |cos(theta_i)| / pdf(wi), pdf in solid angle. A failed
//   sample has pdf = 0 and weight = 0: callers end the path there, nothing NaN travels on.
#include "warps.glsl"
#include "shading_frame.glsl"

struct BsdfSample {
    vec3 wiLocal;
    vec3 weight;
    float pdfSolidAngle;
};

// Lambertian reflection, two-sided: the caller's frame already faces wo.
vec3 lambertianF(vec3 albedo, vec3 woLocal, vec3 wiLocal) {
    return (woLocal.z > 0.0 && wiLocal.z > 0.0) ? albedo * kInvPi : vec3(0.0);
}

float lambertianPdf(vec3 woLocal, vec3 wiLocal) {
    return woLocal.z > 0.0 ? cosineHemispherePdf(wiLocal.z) : 0.0;
}

BsdfSample sampleLambertian(vec3 albedo, vec3 woLocal, vec2 u) {
    vec3 wiLocal = sampleCosineHemisphere(u);
    float pdf = lambertianPdf(woLocal, wiLocal);
    if (pdf == 0.0) return BsdfSample(wiLocal, vec3(0.0), 0.0);
    // albedo/pi * cos / (cos/pi): the cosine cancels exactly.
    return BsdfSample(wiLocal, albedo, pdf);
}
