// Perfect mirror: delta, so f and pdf are 0 for any given direction; only sampling finds its one
// direction.
#include "bsdf_common.glsl"
#include "material.glsl"

// Perfect mirror, no Fresnel: a constant reflectance on either side.
BsdfSample sampleMirror(vec3 reflectance, vec3 woLocal) {
    if (woLocal.z == 0.0) return failedBsdfSample();
    return BsdfSample(reflectLocal(woLocal), reflectance, 1.0, true);
}

// ---- Entry points of the generated dispatch (bsdf.glsl, renderer/gpu/ShaderFeatures.cpp names
// them NAMEBsdfF / NAMEBsdfPdf / NAMEBsdfSample): what the model reads of a Material, said once.
BsdfSample mirrorBsdfSample(Material material, vec3 woLocal, float uLobe, vec2 u) { return sampleMirror(material.color, woLocal); }
