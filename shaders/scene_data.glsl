// Scene data as the GPU sees it: buffer textures filled by renderer/GpuScene.cpp. Buffer textures
// (not SSBOs) keep the fragment path within OpenGL 4.1.
#include "material.glsl"

uniform samplerBuffer uSpheres;        // per sphere: (center.xyz, radius)
uniform isamplerBuffer uSphereIds;     // per sphere: (material, light index or -1)
uniform samplerBuffer uQuads;          // per quad: center, u, v, dual = cross(u, v) / |cross(u, v)|^2
uniform isamplerBuffer uQuadIds;
uniform samplerBuffer uDisks;          // per disk: (center, radius), (unit normal, -)
uniform isamplerBuffer uDiskIds;
uniform samplerBuffer uMaterialParams; // per material: (color, ior), (radiance, roughness)
uniform usamplerBuffer uMaterialTypes;
uniform samplerBuffer uLights;         // per light: 4 texels, see lights.glsl
uniform samplerBuffer uLightCdf;       // cumulative selection probability, by emitted power
uniform int uSphereCount;
uniform int uQuadCount;
uniform int uDiskCount;
uniform int uLightCount;
uniform int uEnvironmentLight;         // light index of the environment, or -1 when it is black

Material fetchMaterial(int index) {
    vec4 colorAndIor = texelFetch(uMaterialParams, 2 * index);
    vec4 radianceAndRoughness = texelFetch(uMaterialParams, 2 * index + 1);
    return Material(texelFetch(uMaterialTypes, index).r, colorAndIor.rgb, colorAndIor.a,
                    radianceAndRoughness.rgb, radianceAndRoughness.a);
}
