// Plastic: a Lambertian base under a dielectric coat, the "Kd/Ks" material users know. The coat
// reflects by Fresnel (smooth when roughness is about 0, else GGX); light reaching the base crosses the
// coat twice, so the base is weighted by (1 - F(theta_o)) (1 - F(theta_i)). Both weights stay
// below what the coat lets through, so the sum never reflects more than arrives. Two-sided.
#include "bsdf_common.glsl"
#include "material.glsl"
#include "fresnel.glsl"
#include "microfacet.glsl"
#include "warps.glsl"

bool plasticIsSmooth(float roughness) {
    return ggxIsEffectivelySmooth(ggxAlpha(roughness));
}

// Probability of sampling the coat: its reflectance toward wo against what the base returns.
float plasticCoatProbability(vec3 albedo, float ior, float cosThetaO) {
    float coat = fresnelDielectric(cosThetaO, ior);
    float base = (1.0 - coat) * luminance(albedo);
    return coat + base > 0.0 ? coat / (coat + base) : 1.0;
}

vec3 plasticF(vec3 albedo, float ior, float roughness, vec3 woLocal, vec3 wiLocal) {
    if (!sameHemisphere(woLocal, wiLocal)) return vec3(0.0);
    float side = frontSide(woLocal);
    vec3 wo = flipToSide(woLocal, side);
    vec3 wi = flipToSide(wiLocal, side);
    vec3 base = (1.0 - fresnelDielectric(wo.z, ior)) * (1.0 - fresnelDielectric(wi.z, ior)) * albedo * kInvPi;
    if (plasticIsSmooth(roughness)) return base; // the smooth coat is a delta lobe
    vec3 h = wo + wi;
    if (dot(h, h) == 0.0) return base;
    h = normalize(h);
    float alpha = ggxAlpha(roughness);
    float coat = fresnelDielectric(dot(wo, h), ior) * ggxD(h, alpha) * ggxG2(wo, wi, alpha) / (4.0 * wo.z * wi.z);
    return base + vec3(coat);
}

float plasticPdf(vec3 albedo, float ior, float roughness, vec3 woLocal, vec3 wiLocal) {
    if (!sameHemisphere(woLocal, wiLocal)) return 0.0;
    float side = frontSide(woLocal);
    vec3 wo = flipToSide(woLocal, side);
    vec3 wi = flipToSide(wiLocal, side);
    float coatProbability = plasticCoatProbability(albedo, ior, wo.z);
    float pdf = (1.0 - coatProbability) * cosineHemispherePdf(wi.z);
    if (!plasticIsSmooth(roughness)) pdf += coatProbability * ggxReflectionPdf(wo, wi, ggxAlpha(roughness));
    return pdf;
}

BsdfSample samplePlastic(vec3 albedo, float ior, float roughness, vec3 woLocal, float uLobe, vec2 u) {
    if (woLocal.z == 0.0) return failedBsdfSample();
    float side = frontSide(woLocal);
    vec3 wo = flipToSide(woLocal, side);
    float coatProbability = plasticCoatProbability(albedo, ior, wo.z);
    vec3 wi;
    if (uLobe < coatProbability) {
        if (plasticIsSmooth(roughness)) {
            vec3 weight = vec3(fresnelDielectric(wo.z, ior) / coatProbability);
            return BsdfSample(reflectLocal(woLocal), weight, coatProbability, true);
        }
        vec3 h = sampleGgxVisibleNormal(wo, ggxAlpha(roughness), u);
        wi = reflect(-wo, h);
    } else {
        wi = sampleCosineHemisphere(u);
    }
    if (wi.z <= 0.0) return failedBsdfSample();
    vec3 wiLocal = flipToSide(wi, side);
    // One-sample MIS over the lobes: weigh by the density of the whole mixture.
    float pdf = plasticPdf(albedo, ior, roughness, woLocal, wiLocal);
    if (pdf == 0.0) return failedBsdfSample();
    return BsdfSample(wiLocal, plasticF(albedo, ior, roughness, woLocal, wiLocal) * wi.z / pdf, pdf, false);
}

// ---- Entry points of the generated dispatch (bsdf.glsl, renderer/gpu/ShaderFeatures.cpp names
// them NAMEBsdfF / NAMEBsdfPdf / NAMEBsdfSample): what the model reads of a Material, said once.
vec3 plasticBsdfF(Material material, vec3 woLocal, vec3 wiLocal) { return plasticF(material.color, material.ior, material.roughness, woLocal, wiLocal); }
float plasticBsdfPdf(Material material, vec3 woLocal, vec3 wiLocal) { return plasticPdf(material.color, material.ior, material.roughness, woLocal, wiLocal); }
BsdfSample plasticBsdfSample(Material material, vec3 woLocal, float uLobe, vec2 u) { return samplePlastic(material.color, material.ior, material.roughness, woLocal, uLobe, u); }
