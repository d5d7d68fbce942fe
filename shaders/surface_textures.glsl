// Textured materials: texture coordinates at a hit and the material's inputs read there. A
// program for a scene without textures gets surface_textures_none.glsl instead (specialization),
// so it carries none of this.
#include "scene_data.glsl"
#include "mesh_intersect.glsl"
#include "textures.glsl"
#include "texture_slots.glsl"

// Quads: center + a u + b v with (a, b) in [-1, 1]^2; uv = ((a + 1) / 2, (1 - b) / 2), so an image
// is upright on a quad whose u points right and v up as seen from its front (cross(u, v)).
vec2 quadSurfaceUv(vec3 posWorld, Quad quad) {
    vec3 offset = posWorld - quad.center;
    return vec2(0.5 * (dot(offset, quad.reciprocalU) + 1.0), 0.5 * (1.0 - dot(offset, quad.reciprocalV)));
}

// Spheres: equirectangular from the outward normal, v = 0 at +y (the top), u = 0.5 toward +z,
// growing toward +x.
vec2 sphereSurfaceUv(vec3 normal) {
    return vec2(0.5 + atan(normal.x, normal.z) * (0.5 * kInvPi), acos(clamp(normal.y, -1.0, 1.0)) * kInvPi);
}

// Meshes: the corners' texture coordinates, interpolated. Disks have none (uv = 0).
vec2 meshSurfaceUv(MeshHit hit) {
    return meshUv(hit);
}

// A material's slot k (0 base colour, 1 roughness, 2 metallic, 3 normal, 4 emission) at uv.
vec4 materialTexture(int material, int texture, int slot, vec2 uv) {
    vec4 scaleOffset = texelFetch(uMaterials, kMaterialTexels * material + 5 + slot);
    return sampleTexture(texture, uv * scaleOffset.xy + scaleOffset.zw);
}

// The material with its textured inputs evaluated at uv: factor x texture, base colour RGB,
// roughness G, metallic B, emission RGB (docs/materials.md). Inputs no material of the scene
// textures are compiled out (texture_slots.glsl).
Material fetchSurfaceMaterial(int index, vec2 uv) {
    Material material = fetchMaterial(index);
    vec4 textures = texelFetch(uMaterials, kMaterialTexels * index + 4);
    float emissionTexture = texelFetch(uMaterials, kMaterialTexels * index + 3).w;
    if (kBaseColorTextured && textures.x >= 0.0) material.color *= materialTexture(index, int(textures.x), 0, uv).rgb;
    vec4 roughnessTexel = vec4(1.0);
    if (kRoughnessTextured && textures.y >= 0.0) {
        roughnessTexel = materialTexture(index, int(textures.y), 1, uv);
        material.roughness *= roughnessTexel.g;
    }
    if (kMetallicTextured && textures.z >= 0.0)
        material.metallic *= (kMetallicFromRoughnessTexel ? roughnessTexel : materialTexture(index, int(textures.z), 2, uv)).b;
    if (kEmissionTextured && emissionTexture >= 0.0)
        material.radiance *= materialTexture(index, int(emissionTexture), 4, uv).rgb;
    return material;
}
