// The BSDF of a material: f, pdf and sampling, dispatched on the material type. The conventions
// (directions, frames, what f and a sample's weight are) are at the top of bsdf_common.glsl.
#include "material.glsl"
#include "bsdf_common.glsl"
#include "bsdf_diffuse.glsl"
#include "bsdf_specular.glsl"
#include "bsdf_metal.glsl"
#include "bsdf_plastic.glsl"

vec3 bsdfF(Material material, vec3 woLocal, vec3 wiLocal) {
    switch (material.type) {
    case kMaterialDiffuse: return lambertianReflectionF(material.color, woLocal, wiLocal);
    case kMaterialDiffuseTransmission: return lambertianTransmissionF(material.color, woLocal, wiLocal);
    case kMaterialMetal: return metalF(material.color, material.roughness, woLocal, wiLocal);
    case kMaterialPlastic: return plasticF(material.color, material.ior, material.roughness, woLocal, wiLocal);
    default: return vec3(0.0); // delta models and emitters
    }
}

float bsdfPdf(Material material, vec3 woLocal, vec3 wiLocal) {
    switch (material.type) {
    case kMaterialDiffuse: return lambertianReflectionPdf(woLocal, wiLocal);
    case kMaterialDiffuseTransmission: return lambertianTransmissionPdf(woLocal, wiLocal);
    case kMaterialMetal: return metalPdf(material.roughness, woLocal, wiLocal);
    case kMaterialPlastic: return plasticPdf(material.color, material.ior, material.roughness, woLocal, wiLocal);
    default: return 0.0;
    }
}

// uLobe picks among a model's lobes; u places the direction within the lobe.
BsdfSample sampleBsdf(Material material, vec3 woLocal, float uLobe, vec2 u) {
    switch (material.type) {
    case kMaterialDiffuse: return sampleLambertianReflection(material.color, woLocal, u);
    case kMaterialDiffuseTransmission: return sampleLambertianTransmission(material.color, woLocal, u);
    case kMaterialMirror: return sampleMirror(material.color, woLocal);
    case kMaterialSpecularTransmission: return sampleSpecularTransmission(material.color, material.ior, woLocal);
    case kMaterialGlass: return sampleGlass(material.color, material.ior, woLocal, uLobe);
    case kMaterialMetal: return sampleMetal(material.color, material.roughness, woLocal, u);
    case kMaterialPlastic: return samplePlastic(material.color, material.ior, material.roughness, woLocal, uLobe, u);
    default: return failedBsdfSample(); // emitters reflect nothing
    }
}
