// A surface's material as the shaders see it (mirrors GpuMaterial in renderer/gpudata/GpuLayout.h).
// Its type is one of the kMaterial* constants generated from ptview::MaterialType (enums.glsl);
// what `color` means depends on it: diffuse: albedo; emitter: nothing (radiance only, reflects
// nothing); diffuse_transmission: transmittance; mirror: reflectance; specular_transmission:
// transmittance (with ior); glass: tint (with ior); metal: reflectance at normal incidence (with
// roughness); plastic: albedo of the base (ior and roughness of the coat); principled: base colour
// (with ior, roughness, metallic, transmission).
#include "enums.glsl"

struct Material {
    uint type;
    vec3 color;
    float ior;
    vec3 radiance;
    float roughness;
    float metallic;     // principled
    float transmission; // principled
};
