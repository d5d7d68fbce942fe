// Alpha: whether a surface is there at a hit (glTF alphaMode; docs/materials.md, "Alpha"). The
// coverage is the base colour's alpha factor times its texture's A. MASK: the surface is there
// where the coverage is at least the cutoff, and nowhere else. BLEND, as stochastic transparency:
// a ray passes through with probability 1 - coverage, decided by a hash of the hit point and the
// frame, so that on average a fraction 1 - coverage of the light passes. Camera rays, rays
// between bounces and shadow rays all ask this for every candidate hit (analytic shapes in
// intersect.glsl, triangles in the BVH walks of mesh_intersect.glsl), so a cut-away hit is skipped
// and the walk goes on to what lies behind it. A program for a scene without MASK or BLEND gets
// surface_alpha_none.glsl instead (specialization): there every surface is always there.
#include "enums.glsl"
#include "frame_uniforms.glsl"
#include "rng.glsl"
#include "scene_data.glsl"
#include "textures.glsl"

// A number in [0, 1) that is new for each hit point and frame: BLEND's pass-through decision.
float alphaBlendRandom(vec3 posWorld) {
    uvec3 bits = floatBitsToUint(posWorld);
    uint h = pcgHash(bits.x ^ pcgHash(bits.y ^ pcgHash(bits.z ^ pcgHash(uFrameIndex ^ pcgHash(uSeed)))));
    return uintToUnitFloat(h);
}

bool surfacePresent(int material, vec2 uv, vec3 posWorld) {
    // (alpha mode, alpha cutoff, normal scale, emission texture); alpha is texel 2's w.
    vec4 modeAndCutoff = texelFetch(uMaterials, kMaterialTexels * material + 3);
    uint mode = uint(modeAndCutoff.x); // kAlphaMode* (enums.glsl)
    if (mode == kAlphaModeOpaque) return true;
    float coverage = texelFetch(uMaterials, kMaterialTexels * material + 2).w;
    int baseColorTexture = int(texelFetch(uMaterials, kMaterialTexels * material + 4).x);
    if (baseColorTexture >= 0) {
        vec4 scaleOffset = texelFetch(uMaterials, kMaterialTexels * material + 5);
        coverage *= sampleTexture(baseColorTexture, uv * scaleOffset.xy + scaleOffset.zw).a;
    }
    if (mode == kAlphaModeMask) return coverage >= modeAndCutoff.y;
    return alphaBlendRandom(posWorld) < coverage;
}
