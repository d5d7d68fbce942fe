// Perfect mirror: delta, so f and pdf are 0 for any given direction; only sampling finds its one
// direction.
#include "bsdf_common.glsl"

// Perfect mirror, no Fresnel: a constant reflectance on either side.
BsdfSample sampleMirror(vec3 reflectance, vec3 woLocal) {
    if (woLocal.z == 0.0) return failedBsdfSample();
    return BsdfSample(reflectLocal(woLocal), reflectance, 1.0, true);
}
