// Scene data as the GPU sees it: buffer textures filled by renderer/gpu/GpuScene.cpp. Buffer textures
// (not SSBOs) keep the fragment path within OpenGL 4.1.
#include "material.glsl"

// Few buffers, since OpenGL 4.1 guarantees only 16 texture units to a fragment shader.
uniform samplerBuffer uSpheres;        // per sphere: (center.xyz, radius)
uniform samplerBuffer uQuads;          // per quad: center, u, v, dual = cross(u, v) / |cross(u, v)|^2
uniform samplerBuffer uDisks;          // per disk: (center, radius), (unit normal, -)
uniform isamplerBuffer uPrimitiveIds;  // per sphere, then quad, then disk: (material, light index or -1)
uniform samplerBuffer uMaterials;      // per material: (color, ior), (radiance, roughness), (type, -)
uniform samplerBuffer uLights;         // per light: 4 texels, see lights.glsl
uniform int uSphereCount;
uniform int uQuadCount;
uniform int uDiskCount;
uniform int uLightCount;
uniform int uEnvironmentLight;         // light index of the environment, or -1 when it is black

Material fetchMaterial(int index) {
    vec4 colorAndIor = texelFetch(uMaterials, 3 * index);
    vec4 radianceAndRoughness = texelFetch(uMaterials, 3 * index + 1);
    return Material(uint(texelFetch(uMaterials, 3 * index + 2).x), colorAndIor.rgb, colorAndIor.a,
                    radianceAndRoughness.rgb, radianceAndRoughness.a);
}

ivec2 sphereIds(int sphere) { return texelFetch(uPrimitiveIds, sphere).rg; }
ivec2 quadIds(int quad) { return texelFetch(uPrimitiveIds, uSphereCount + quad).rg; }
ivec2 diskIds(int disk) { return texelFetch(uPrimitiveIds, uSphereCount + uQuadCount + disk).rg; }
