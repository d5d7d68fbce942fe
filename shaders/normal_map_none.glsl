// normal_map.glsl for a program whose scene has no normal map: the same functions, doing nothing.

void quadSurfaceTangents(vec3 u, vec3 v, out vec3 tangent, out vec3 bitangent) { tangent = bitangent = vec3(0.0); }
void sphereSurfaceTangents(vec3 normal, out vec3 tangent, out vec3 bitangent) { tangent = bitangent = vec3(0.0); }
vec3 normalMappedShading(int material, vec2 uv, vec3 normalShading, vec3 normalGeom, vec3 tangent, vec3 bitangent, vec3 woWorld) {
    return normalShading;
}
