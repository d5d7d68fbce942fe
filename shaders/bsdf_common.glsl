// What every BSDF shares. The conventions, which all BSDF code follows:
//
// - Directions point away from the surface: wo toward the viewer (the previous path vertex), wi
//   toward the light (the next vertex), both unit length.
// - Suffix Local = in the shading frame of the surface's shading normal (hit.normalShading: a
//   mesh's interpolated normal, then the normal map where there is one, else the geometric
//   normal), which is NOT turned toward wo: z > 0 is the front side (outward for spheres and
//   boxes, cross(u, v) for quads).
//   wo may lie on either side; two-sided models mirror themselves to wo's side, and dielectrics
//   use ior when wo is outside (z > 0) and 1/ior when it is inside.
// - f(wo, wi) is the BSDF alone; it does NOT include |cos(theta_i)|. f and pdf cover only the
//   non-delta parts of a model: a delta lobe (mirror, smooth glass, smooth coat) is reached only
//   by sampling.
// - A sample's weight is f * |cos(theta_i)| / pdf, with pdf the solid-angle density of the
//   whole sampling strategy (all lobes). For a delta lobe, f and pdf are both "infinite" and the
//   weight is their finite ratio; isDelta says so, and pdfSolidAngle then holds the probability
//   of having chosen that lobe.
// - A failed sample (total internal reflection for a transmission-only model, a direction below
//   the surface) has weight 0 and pdfSolidAngle 0: callers end the path there.
// - Refraction does not scale radiance by 1/eta^2: the factors cancel for every path that enters
//   and leaves a dielectric, as long as camera and lights are outside it (as in Cycles).
#include "constants.glsl"

struct BsdfSample {
    vec3 wiLocal;
    vec3 weight;
    float pdfSolidAngle;
    bool isDelta;
};

BsdfSample failedBsdfSample() {
    return BsdfSample(vec3(0.0, 0.0, 1.0), vec3(0.0), 0.0, false);
}

bool sameHemisphere(vec3 aLocal, vec3 bLocal) {
    return aLocal.z * bLocal.z > 0.0;
}

float absCosTheta(vec3 wLocal) {
    return abs(wLocal.z);
}

vec3 reflectLocal(vec3 woLocal) {
    return vec3(-woLocal.xy, woLocal.z);
}

// Two-sided models are evaluated as if wo were on the front side (an isotropic BSDF is symmetric
// under flipping both z's): frontSide(woLocal) is the sign that takes wo there, and
// flipToSide(w, side) applies it to a direction, and undoes it (it is its own inverse).
float frontSide(vec3 woLocal) {
    return woLocal.z > 0.0 ? 1.0 : -1.0;
}

vec3 flipToSide(vec3 wLocal, float side) {
    return vec3(wLocal.xy, wLocal.z * side);
}

float luminance(vec3 rgb) {
    return dot(rgb, vec3(0.2126, 0.7152, 0.0722));
}
