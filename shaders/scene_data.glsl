// Scene data as the GPU sees it: buffer textures filled by renderer/GpuScene.cpp. Buffer textures
// (not SSBOs) keep the fragment path within OpenGL 4.1.

uniform samplerBuffer uSpheres;        // per sphere: (center.xyz, radius)
uniform usamplerBuffer uSphereMaterials;
uniform samplerBuffer uQuads;          // per quad: center, u, v, dual = cross(u, v) / |cross(u, v)|^2
uniform usamplerBuffer uQuadMaterials;
uniform samplerBuffer uMaterialParams; // per material: albedo, radiance
uniform usamplerBuffer uMaterialTypes;
uniform int uSphereCount;
uniform int uQuadCount;

const uint kMaterialDiffuse = 0u;
const uint kMaterialEmitter = 1u;

struct Material {
    uint type;
    vec3 albedo;
    vec3 radiance;
};

Material fetchMaterial(int index) {
    return Material(texelFetch(uMaterialTypes, index).r,
                    texelFetch(uMaterialParams, 2 * index).rgb,
                    texelFetch(uMaterialParams, 2 * index + 1).rgb);
}
