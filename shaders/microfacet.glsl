// The GGX (Trowbridge-Reitz) microfacet distribution, isotropic, in the local frame (+z is the
// macro-surface normal, directions on the +z side). alpha is the GGX width parameter; materials
// expose roughness with alpha = roughness^2 (see ggxAlpha).
#include "constants.glsl"

// Perceptually even steps for users: alpha = roughness^2.
float ggxAlpha(float roughness) {
    return roughness * roughness;
}

// Below this width D is a spike that float cannot resolve (a sampled direction's pdf would not
// survive re-evaluation), so models treat the surface as perfectly smooth: a delta lobe.
bool ggxIsEffectivelySmooth(float alpha) {
    return alpha < 1e-3;
}

// Normal distribution D(h), a density of microfacet normals per projected area (D * cos integrates
// to 1 over the hemisphere).
// Written with sin^2 from the x, y components: the textbook 1 + cos^2 (alpha^2 - 1) cancels
// catastrophically near the peak when alpha is small.
float ggxD(vec3 hLocal, float alpha) {
    float alpha2 = alpha * alpha;
    float denom = dot(hLocal.xy, hLocal.xy) + hLocal.z * hLocal.z * alpha2;
    return alpha2 / (kPi * denom * denom);
}

// Smith's Lambda for GGX, with tan^2 from the x, y components for the same reason as ggxD.
float ggxLambda(vec3 wLocal, float alpha) {
    float cos2 = wLocal.z * wLocal.z;
    if (cos2 <= 0.0) return 1e30;
    float tan2 = dot(wLocal.xy, wLocal.xy) / cos2;
    return 0.5 * (sqrt(1.0 + alpha * alpha * tan2) - 1.0);
}

float ggxG1(vec3 wLocal, float alpha) {
    return 1.0 / (1.0 + ggxLambda(wLocal, alpha));
}

// Height-correlated shadowing-masking.
float ggxG2(vec3 woLocal, vec3 wiLocal, float alpha) {
    return 1.0 / (1.0 + ggxLambda(woLocal, alpha) + ggxLambda(wiLocal, alpha));
}

// Samples a normal from the distribution of normals visible from wo (Heitz 2018), wo.z > 0.
vec3 sampleGgxVisibleNormal(vec3 woLocal, float alpha, vec2 u) {
    vec3 woStretched = normalize(vec3(alpha * woLocal.xy, woLocal.z));
    float lengthSquared = dot(woStretched.xy, woStretched.xy);
    vec3 t1 = lengthSquared > 0.0 ? vec3(-woStretched.y, woStretched.x, 0.0) * inversesqrt(lengthSquared)
                                  : vec3(1.0, 0.0, 0.0);
    vec3 t2 = cross(woStretched, t1);
    float r = sqrt(u.x);
    float phi = kTwoPi * u.y;
    float p1 = r * cos(phi);
    float p2 = r * sin(phi);
    float s = 0.5 * (1.0 + woStretched.z);
    p2 = (1.0 - s) * sqrt(max(0.0, 1.0 - p1 * p1)) + s * p2;
    vec3 hStretched = p1 * t1 + p2 * t2 + sqrt(max(0.0, 1.0 - p1 * p1 - p2 * p2)) * woStretched;
    return normalize(vec3(alpha * hStretched.xy, max(hStretched.z, 1e-7)));
}

// Density of sampleGgxVisibleNormal over normals (solid angle of h).
float ggxVisibleNormalPdf(vec3 woLocal, vec3 hLocal, float alpha) {
    return ggxG1(woLocal, alpha) * max(dot(woLocal, hLocal), 0.0) * ggxD(hLocal, alpha) / woLocal.z;
}

// Solid-angle density of the reflected direction wi when h is sampled from visible normals.
float ggxReflectionPdf(vec3 woLocal, vec3 wiLocal, float alpha) {
    vec3 h = woLocal + wiLocal;
    if (woLocal.z <= 0.0 || wiLocal.z <= 0.0 || dot(h, h) == 0.0) return 0.0;
    h = normalize(h);
    return ggxVisibleNormalPdf(woLocal, h, alpha) / (4.0 * dot(woLocal, h));
}
