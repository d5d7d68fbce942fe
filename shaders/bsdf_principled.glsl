// Principled: glTF's metallic-roughness material, as a mixture of three of our models that share
// its base colour, roughness and ior (docs/materials.md has the exact model):
//   (1 - metallic) (1 - transmission)  plastic: Lambertian base colour under a GGX dielectric coat
//                                      (exact Fresnel of ior; at ior 1.5 F0 = 0.04, glTF's value)
//   (1 - metallic) transmission        glass tinted by the base colour (smooth whatever the
//                                      roughness: KHR_materials_transmission on our dielectric)
//   metallic                           metal: GGX with Schlick's Fresnel from F0 = base colour
// Linear in metallic, as glTF's mix(dielectric, metal, metallic) (so the specular F0 is
// mix(F0(ior), base, metallic)). Each part keeps its own sampling; a part is chosen by its
// weight times an estimate of its albedo toward wo, and a non-delta sample is weighed by the
// density of the whole mixture (one-sample MIS), so f, pdf and sample agree.
#include "bsdf_common.glsl"
#include "material.glsl"
#include "bsdf_plastic.glsl"
#include "bsdf_metal.glsl"
#include "bsdf_dielectric.glsl"

// The three parts' weights: (plastic, glass, metal); they sum to 1.
vec3 principledWeights(float metallic, float transmission) {
    return vec3((1.0 - metallic) * (1.0 - transmission), (1.0 - metallic) * transmission, metallic);
}

// Probabilities of sampling each part. The albedo estimates are floored so that a part with
// weight > 0 is always sampled with probability > 0 (its f may be nonzero where the estimate is 0).
vec3 principledPartProbabilities(vec3 base, float ior, float metallic, float transmission, float cosThetaO) {
    vec3 weights = principledWeights(metallic, transmission);
    float coat = fresnelDielectric(abs(cosThetaO), ior);
    vec3 albedo = vec3(coat + (1.0 - coat) * luminance(base), luminance(base),
                       luminance(fresnelSchlick(base, abs(cosThetaO))));
    vec3 p = weights * max(albedo, vec3(0.05));
    float total = p.x + p.y + p.z;
    return total > 0.0 ? p / total : vec3(1.0, 0.0, 0.0);
}

vec3 principledF(vec3 base, float ior, float roughness, float metallic, float transmission, vec3 woLocal, vec3 wiLocal) {
    vec3 weights = principledWeights(metallic, transmission);
    vec3 f = vec3(0.0);
    if (weights.x > 0.0) f += weights.x * plasticF(base, ior, roughness, woLocal, wiLocal);
    if (weights.z > 0.0) f += weights.z * metalF(base, roughness, woLocal, wiLocal);
    return f; // the glass part is delta only
}

float principledPdf(vec3 base, float ior, float roughness, float metallic, float transmission, vec3 woLocal, vec3 wiLocal) {
    vec3 p = principledPartProbabilities(base, ior, metallic, transmission, woLocal.z);
    float pdf = 0.0;
    if (p.x > 0.0) pdf += p.x * plasticPdf(base, ior, roughness, woLocal, wiLocal);
    if (p.z > 0.0) pdf += p.z * metalPdf(roughness, woLocal, wiLocal);
    return pdf;
}

BsdfSample samplePrincipled(vec3 base, float ior, float roughness, float metallic, float transmission, vec3 woLocal,
                            float uLobe, vec2 u) {
    if (woLocal.z == 0.0) return failedBsdfSample();
    vec3 weights = principledWeights(metallic, transmission);
    vec3 p = principledPartProbabilities(base, ior, metallic, transmission, woLocal.z);
    BsdfSample bs;
    float chosenWeight;
    float chosenProbability;
    // uLobe picks the part, and what is left of it (rescaled to [0, 1)) the lobe within it.
    if (uLobe < p.x || (p.y == 0.0 && p.z == 0.0)) {
        chosenWeight = weights.x;
        chosenProbability = p.x;
        bs = samplePlastic(base, ior, roughness, woLocal, min(uLobe / p.x, 0.99999994), u);
    } else if (uLobe < p.x + p.y || p.z == 0.0) {
        chosenWeight = weights.y;
        chosenProbability = p.y;
        bs = sampleGlass(base, ior, woLocal, clamp((uLobe - p.x) / p.y, 0.0, 0.99999994));
    } else {
        chosenWeight = weights.z;
        chosenProbability = p.z;
        bs = sampleMetal(base, roughness, woLocal, u);
    }
    if (bs.pdfSolidAngle == 0.0 || chosenProbability <= 0.0) return failedBsdfSample();
    if (bs.isDelta) {
        // Only this part has this direction: its weight scaled by part weight / part probability.
        return BsdfSample(bs.wiLocal, bs.weight * (chosenWeight / chosenProbability), bs.pdfSolidAngle * chosenProbability, true);
    }
    float pdf = principledPdf(base, ior, roughness, metallic, transmission, woLocal, bs.wiLocal);
    if (!(pdf > 0.0)) return failedBsdfSample();
    vec3 f = principledF(base, ior, roughness, metallic, transmission, woLocal, bs.wiLocal);
    return BsdfSample(bs.wiLocal, f * absCosTheta(bs.wiLocal) / pdf, pdf, false);
}

// ---- Entry points of the generated dispatch (bsdf.glsl, renderer/gpu/ShaderFeatures.cpp names
// them NAMEBsdfF / NAMEBsdfPdf / NAMEBsdfSample): what the model reads of a Material, said once.
vec3 principledBsdfF(Material material, vec3 woLocal, vec3 wiLocal) { return principledF(material.color, material.ior, material.roughness, material.metallic, material.transmission, woLocal, wiLocal); }
float principledBsdfPdf(Material material, vec3 woLocal, vec3 wiLocal) { return principledPdf(material.color, material.ior, material.roughness, material.metallic, material.transmission, woLocal, wiLocal); }
BsdfSample principledBsdfSample(Material material, vec3 woLocal, float uLobe, vec2 u) { return samplePrincipled(material.color, material.ior, material.roughness, material.metallic, material.transmission, woLocal, uLobe, u); }
