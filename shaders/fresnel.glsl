// Fresnel reflectance.

// Exact unpolarized reflectance of a smooth dielectric interface. cosThetaI is measured against
// the normal on the side eta is given for (eta = n_other_side / n_this_side); a negative cosine
// means the light arrives from the other side, so the ratio is inverted. 1 under total internal
// reflection.
float fresnelDielectric(float cosThetaI, float eta) {
    cosThetaI = clamp(cosThetaI, -1.0, 1.0);
    if (cosThetaI < 0.0) {
        eta = 1.0 / eta;
        cosThetaI = -cosThetaI;
    }
    float sin2ThetaT = (1.0 - cosThetaI * cosThetaI) / (eta * eta);
    if (sin2ThetaT >= 1.0) return 1.0;
    float cosThetaT = sqrt(max(0.0, 1.0 - sin2ThetaT));
    float rParallel = (eta * cosThetaI - cosThetaT) / (eta * cosThetaI + cosThetaT);
    float rPerpendicular = (cosThetaI - eta * cosThetaT) / (cosThetaI + eta * cosThetaT);
    return 0.5 * (rParallel * rParallel + rPerpendicular * rPerpendicular);
}

// Schlick's approximation for conductors, per channel from the reflectance at normal incidence.
vec3 fresnelSchlick(vec3 reflectanceAtNormal, float cosTheta) {
    float m = clamp(1.0 - cosTheta, 0.0, 1.0);
    float m2 = m * m;
    return reflectanceAtNormal + (1.0 - reflectanceAtNormal) * (m2 * m2 * m);
}

// Refracts wLocal (pointing away from the surface, on either side) through the interface whose
// normal is +z, with eta = n_inside / n_outside for z > 0 outside. Returns false under total
// internal reflection. etaRelative is n_transmitted / n_incident along this refraction.
bool refractLocal(vec3 wLocal, float eta, out vec3 wtLocal, out float etaRelative) {
    float cosThetaI = wLocal.z;
    vec3 n = vec3(0.0, 0.0, 1.0);
    if (cosThetaI < 0.0) {
        eta = 1.0 / eta;
        cosThetaI = -cosThetaI;
        n = -n;
    }
    float sin2ThetaT = max(0.0, 1.0 - cosThetaI * cosThetaI) / (eta * eta);
    etaRelative = eta;
    wtLocal = vec3(0.0);
    if (sin2ThetaT >= 1.0) return false;
    float cosThetaT = sqrt(max(0.0, 1.0 - sin2ThetaT));
    wtLocal = normalize(-wLocal / eta + (cosThetaI / eta - cosThetaT) * n);
    return true;
}
