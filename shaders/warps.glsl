// Warps from the unit square to other domains, each beside its density.
#include "constants.glsl"

// Cosine-weighted directions on the hemisphere around +z (Malley's method on a polar disk).
vec3 sampleCosineHemisphere(vec2 u) {
    float r = sqrt(u.x);
    float phi = kTwoPi * u.y;
    return vec3(r * cos(phi), r * sin(phi), sqrt(max(0.0, 1.0 - u.x)));
}

// Solid-angle density of sampleCosineHemisphere.
float cosineHemispherePdf(float cosTheta) {
    return max(cosTheta, 0.0) * kInvPi;
}
