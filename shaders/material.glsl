// A surface's material as the shaders see it (mirrors GpuMaterial in renderer/gpu/GpuLayout.h; the
// type values follow ptview::MaterialType).
const uint kMaterialDiffuse = 0u;              // color = albedo
const uint kMaterialEmitter = 1u;              // radiance; reflects nothing
const uint kMaterialDiffuseTransmission = 2u;  // color = transmittance
const uint kMaterialMirror = 3u;               // color = reflectance
const uint kMaterialSpecularTransmission = 4u; // color = transmittance, ior
const uint kMaterialGlass = 5u;                // color = tint, ior
const uint kMaterialMetal = 6u;                // color = reflectance at normal incidence, roughness
const uint kMaterialPlastic = 7u;              // color = albedo of the base, ior and roughness of the coat
const uint kMaterialPrincipled = 8u;           // color = base colour, ior, roughness, metallic, transmission

struct Material {
    uint type;
    vec3 color;
    float ior;
    vec3 radiance;
    float roughness;
    float metallic;     // principled
    float transmission; // principled
};
