// surface_textures.glsl for a program whose scene has no textured material: the same functions,
// without texture coordinates.
#include "scene_data.glsl"
#include "mesh_intersect.glsl"

vec2 quadSurfaceUv(vec3 posWorld, Quad quad) { return vec2(0.0); }
vec2 sphereSurfaceUv(vec3 normal) { return vec2(0.0); }
vec2 meshSurfaceUv(MeshHit hit) { return vec2(0.0); }
Material fetchSurfaceMaterial(int index, vec2 uv) { return fetchMaterial(index); }
