// The BSDF of a material: f, pdf and sampling, dispatched on the material type, for the models
// this program was built for: diffuse, emitter, diffuse_transmission, mirror, specular_transmission, glass, metal, plastic, principled, medium.
// Generated for each program by generateBsdfDispatch (renderer/gpu/ShaderFeatures.cpp), so that
// it compiles only the models its scene uses; shaders/bsdf.glsl is the output for every model.
// The conventions are at the top of bsdf_common.glsl.
#include "material.glsl"
#include "bsdf_common.glsl"
#include "bsdf_diffuse.glsl"
#include "bsdf_mirror.glsl"
#include "bsdf_dielectric.glsl"
#include "bsdf_metal.glsl"
#include "bsdf_plastic.glsl"
#include "bsdf_principled.glsl"

// Whether some model here may scatter by delta lobes alone (a mirror, glass, smooth metal): the
// denoiser's features look through such surfaces (denoise_features.frag).
const bool kPurelySpecularModels = true;
// Whether some model here may scatter by a delta lobe at all (those, and a smooth coat): the
// features follow the path through them to the emission it meets (denoise_features.frag).
const bool kDeltaLobeModels = true;

vec3 bsdfF(Material material, vec3 woLocal, vec3 wiLocal) {
    switch (material.type) {
    case kMaterialDiffuse: return lambertianReflectionBsdfF(material, woLocal, wiLocal);
    case kMaterialDiffuseTransmission: return lambertianTransmissionBsdfF(material, woLocal, wiLocal);
    case kMaterialMetal: return metalBsdfF(material, woLocal, wiLocal);
    case kMaterialPlastic: return plasticBsdfF(material, woLocal, wiLocal);
    case kMaterialPrincipled: return principledBsdfF(material, woLocal, wiLocal);
    default: return vec3(0.0); // delta models and emitters
    }
}

float bsdfPdf(Material material, vec3 woLocal, vec3 wiLocal) {
    switch (material.type) {
    case kMaterialDiffuse: return lambertianReflectionBsdfPdf(material, woLocal, wiLocal);
    case kMaterialDiffuseTransmission: return lambertianTransmissionBsdfPdf(material, woLocal, wiLocal);
    case kMaterialMetal: return metalBsdfPdf(material, woLocal, wiLocal);
    case kMaterialPlastic: return plasticBsdfPdf(material, woLocal, wiLocal);
    case kMaterialPrincipled: return principledBsdfPdf(material, woLocal, wiLocal);
    default: return 0.0;
    }
}

// uLobe picks among a model's lobes; u places the direction within the lobe.
BsdfSample sampleBsdf(Material material, vec3 woLocal, float uLobe, vec2 u) {
    switch (material.type) {
    case kMaterialDiffuse: return lambertianReflectionBsdfSample(material, woLocal, uLobe, u);
    case kMaterialDiffuseTransmission: return lambertianTransmissionBsdfSample(material, woLocal, uLobe, u);
    case kMaterialMirror: return mirrorBsdfSample(material, woLocal, uLobe, u);
    case kMaterialSpecularTransmission: return specularTransmissionBsdfSample(material, woLocal, uLobe, u);
    case kMaterialGlass: return glassBsdfSample(material, woLocal, uLobe, u);
    case kMaterialMetal: return metalBsdfSample(material, woLocal, uLobe, u);
    case kMaterialPlastic: return plasticBsdfSample(material, woLocal, uLobe, u);
    case kMaterialPrincipled: return principledBsdfSample(material, woLocal, uLobe, u);
    default: return failedBsdfSample(); // emitters reflect nothing
    }
}
