// Scene data as the GPU sees it: buffer textures filled by renderer/gpu/GpuScene.cpp. Buffer textures
// (not SSBOs) keep the fragment path within OpenGL 4.1.
#include "material.glsl"

// Few buffers, since OpenGL 4.1 guarantees only 16 texture units to a fragment shader.
uniform samplerBuffer uSpheres;        // per sphere: (center.xyz, radius)
uniform samplerBuffer uQuads;          // per quad: center, u, v, dual = cross(u, v) / |cross(u, v)|^2
uniform samplerBuffer uDisks;          // per disk: (center, radius), (unit normal, -)
uniform isamplerBuffer uPrimitiveIds;  // per sphere, then quad, then disk: (material, light index or -1)
uniform samplerBuffer uMaterials;      // per material: kMaterialTexels texels; then the texture records (textures.glsl)
uniform samplerBuffer uLights;         // per light: 4 texels, see lights.glsl
uniform int uSphereCount;
uniform int uQuadCount;
uniform int uDiskCount;
uniform int uLightCount;
uniform int uEnvironmentLight;         // light index of the environment, or -1 when it is black

// GpuMaterial (GpuLayout.h): (color, ior), (radiance, roughness), (type, metallic, transmission,
// alpha), (alpha mode, alpha cutoff, normal scale, emission texture), (base colour, roughness,
// metallic, normal texture), then per texture slot in that order (scale.xy, offset.xy).
const int kMaterialTexels = 10;

Material fetchMaterial(int index) {
    vec4 colorAndIor = texelFetch(uMaterials, kMaterialTexels * index);
    vec4 radianceAndRoughness = texelFetch(uMaterials, kMaterialTexels * index + 1);
    vec4 typeMetallicTransmissionAlpha = texelFetch(uMaterials, kMaterialTexels * index + 2);
    return Material(uint(typeMetallicTransmissionAlpha.x), colorAndIor.rgb, colorAndIor.a, radianceAndRoughness.rgb,
                    radianceAndRoughness.a, typeMetallicTransmissionAlpha.y, typeMetallicTransmissionAlpha.z);
}

ivec2 sphereIds(int sphere) { return texelFetch(uPrimitiveIds, sphere).rg; }
ivec2 quadIds(int quad) { return texelFetch(uPrimitiveIds, uSphereCount + quad).rg; }
ivec2 diskIds(int disk) { return texelFetch(uPrimitiveIds, uSphereCount + uQuadCount + disk).rg; }
