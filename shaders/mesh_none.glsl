// Ray queries for a scene without triangle meshes: the same two functions as mesh_intersect.glsl,
// which specialization (renderer/gpu/ShaderFeatures.cpp) replaces by these, so such a scene's
// program carries no BVH traversal at all.
#include "constants.glsl"
#include "ray.glsl"

struct MeshHit {
    int instance;
    int triangle;
    vec3 barycentric;
};

bool traverseMeshes(Ray worldRay, inout float tBest, inout MeshHit best, bool anyHit, int excludedLight) {
    return false;
}

void meshSurface(MeshHit hit, out vec3 normalGeom, out vec3 normalShading, out int material, out int light) {
    normalGeom = vec3(0.0, 0.0, 1.0);
    normalShading = normalGeom;
    material = 0;
    light = -1;
}

vec2 meshUv(MeshHit hit) {
    return vec2(0.0);
}

void meshSurfaceTangents(MeshHit hit, out vec3 tangent, out vec3 bitangent) {
    tangent = bitangent = vec3(0.0);
}
