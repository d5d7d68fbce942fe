// Scene data as the GPU sees it: buffer textures filled by renderer/gpu/GpuScene.cpp. Buffer textures
// (not SSBOs) keep the fragment path within OpenGL 4.1.
#include "gpu_layout.glsl"
#include "material.glsl"

// Few buffers, since OpenGL 4.1 guarantees only 16 texture units to a fragment shader.
uniform samplerBuffer uSpheres;        // per sphere: (center.xyz, radius)
uniform samplerBuffer uQuads;          // per quad: kQuadTexels texels, see fetchQuad
uniform samplerBuffer uDisks;          // per disk: (center, radius), (unit normal, -)
uniform isamplerBuffer uPrimitiveIds;  // per sphere, then quad, then disk: (material, light index or -1)
uniform samplerBuffer uMaterials;      // per material: kMaterialTexels texels; then the texture records (textures.glsl)
uniform samplerBuffer uLights;         // per light: kLightTexels texels, see lights.glsl
uniform int uSphereCount;
uniform int uQuadCount;
uniform int uDiskCount;
uniform int uLightCount;
uniform int uEnvironmentLight;         // light index of the environment, or -1 when it is black

// GpuMaterial (GpuLayout.h): (color, ior), (radiance, roughness), (type, metallic, transmission,
// alpha), (alpha mode, alpha cutoff, normal scale, emission texture), (base colour, roughness,
// metallic, normal texture), then per texture slot in that order (scale.xy, offset.xy).

Material fetchMaterial(int index) {
    vec4 colorAndIor = texelFetch(uMaterials, kMaterialTexels * index);
    vec4 radianceAndRoughness = texelFetch(uMaterials, kMaterialTexels * index + 1);
    vec4 typeMetallicTransmissionAlpha = texelFetch(uMaterials, kMaterialTexels * index + 2);
    return Material(uint(typeMetallicTransmissionAlpha.x), colorAndIor.rgb, colorAndIor.a, radianceAndRoughness.rgb,
                    radianceAndRoughness.a, typeMetallicTransmissionAlpha.y, typeMetallicTransmissionAlpha.z);
}

// Quad i is the parallelogram center +- u +- v, front side along normal = cross(u, v). For its ray
// test (intersect.glsl intersectQuad) it also carries the reciprocal basis of (u, v) in its plane:
// reciprocalU = cross(v, dual), reciprocalV = cross(dual, u) with dual = normal / |normal|^2, so a
// point's offset from the center has coordinate dot(offset, reciprocalU) along u and
// dot(offset, reciprocalV) along v; and the magnitudes the test's rounding bound needs. All
// computed once on the CPU (renderer/gpu/GpuScene.cpp makeQuad), not in every ray test: the ray
// tests over every quad are most of a path's work. GpuQuad (GpuLayout.h) mirrors the texels:
//   (center, max |component| of center), (normal, -), (reciprocalU, its |x| + |y| + |z|),
//   (reciprocalV, its |x| + |y| + |z|), (u, -), (v, -)

struct Quad {
    vec3 center;
    float centerMagnitude; // max |component|
    vec3 reciprocalU;
    float reciprocalUSum;  // |x| + |y| + |z| of reciprocalU
    vec3 reciprocalV;
    float reciprocalVSum;
};

// What a ray test reads: three texels. Its plane's normal is cross(reciprocalU, reciprocalV)
// there (parallel to cross(u, v)): on llvmpipe a cross product costs less than a fourth texel
// read in the loops over every quad. quadNormal and quadEdges read the rest where it is needed.
Quad fetchQuad(int quad) {
    vec4 centerAndMagnitude = texelFetch(uQuads, kQuadTexels * quad);
    vec4 reciprocalU = texelFetch(uQuads, kQuadTexels * quad + 2);
    vec4 reciprocalV = texelFetch(uQuads, kQuadTexels * quad + 3);
    return Quad(centerAndMagnitude.xyz, centerAndMagnitude.w, reciprocalU.xyz, reciprocalU.w, reciprocalV.xyz,
                reciprocalV.w);
}

vec3 quadCenter(int quad) {
    return texelFetch(uQuads, kQuadTexels * quad).xyz;
}

// cross(u, v): the front side.
vec3 quadNormal(int quad) {
    return texelFetch(uQuads, kQuadTexels * quad + 1).xyz;
}

// The half-edges u and v of a quad.
void quadEdges(int quad, out vec3 u, out vec3 v) {
    u = texelFetch(uQuads, kQuadTexels * quad + 4).xyz;
    v = texelFetch(uQuads, kQuadTexels * quad + 5).xyz;
}

ivec2 sphereIds(int sphere) { return texelFetch(uPrimitiveIds, sphere).rg; }
ivec2 quadIds(int quad) { return texelFetch(uPrimitiveIds, uSphereCount + quad).rg; }
ivec2 diskIds(int disk) { return texelFetch(uPrimitiveIds, uSphereCount + uQuadCount + disk).rg; }

uvec2 lightKindAndPrimitive(int light) {
    return uvec2(texelFetch(uLights, kLightTexels * light).xy); // exact small integers, stored as float values
}
