#pragma once
// What a scene calls for (material models, kinds of light, environment map, meshes, textures, a
// lens, its shape counts), found without OpenGL; gpu/ShaderFeatures.h specializes the program
// for it.

#include <ptview/gpudata/LightKind.h>
#include <ptview/scene/Scene.h>

#include <cstdint>
#include <optional>
#include <string>

namespace ptview {

// How many spheres, quads and disks (a box is six quads) a scene's shapes make.
struct ShapeCounts {
    int spheres = 0;
    int quads = 0;
    int disks = 0;

    int total() const { return spheres + quads + disks; }
    bool operator==(const ShapeCounts& other) const;
};

// As flattenScene (GpuScene.h) lays them out for the GPU.
ShapeCounts shapeCounts(const Scene& scene);

struct ShaderFeatures {
    std::uint32_t materialModels = 0; // bit (1 << MaterialType) for each model a shape uses
    std::uint32_t lightKinds = 0;     // bit (1 << LightKind) for each kind of light the scene can
                                      //   have in its light table (emitting shapes, triangles, the
                                      //   environment, point lights...): only those are sampled
    bool quadLightsUpClose = false;   // a surface comes near enough a quad light's front to sample
                                      //   it by solid angle (QuadLightReach.h); else only by area
    bool environmentMap = false;      // else the constant colour
    bool meshes = false;
    bool oneMeshInstance = false;     // exactly one mesh shape: its walk needs no top level
                                      //   (mesh_instances.glsl); the program then covers no scene
                                      //   of more
    bool textures = false;            // a material a shape uses has a texture (surface_textures.glsl)
    std::uint32_t textureSlots = 0;   // bit k: ... has a texture in input k of kMaterialTextureInputs
                                      //   (MaterialTextures.h): only those inputs are read
                                      //   (texture_slots.glsl)
    bool metallicFromRoughnessTexel = false; // every material with a metallic texture reads it from its
                                      //   roughness texture with the same scale and offset (glTF's
                                      //   metallicRoughness): one lookup serves both
    bool thinLens = false;            // the camera has an aperture (camera_thin_lens.glsl), else a pinhole
    bool normalMaps = false;          // ... a normal map (normal_map.glsl); implies textures
    bool alpha = false;               // ... alpha mode MASK or BLEND (surface_alpha.glsl); implies
                                      //   textures, since the coverage is read at texture coordinates
    bool media = false;               // a shape bounds a participating medium (media.glsl)
    // The loops over every sphere, quad and disk unrolled for exactly these counts
    // (shape_loops.glsl), or none: loops over the counts the scene sets at run time (the uber
    // program, and scenes of more than kMaxUnrolledShapes shapes).
    std::optional<ShapeCounts> unrolledShapes;

    // Unrolled, each shape's ray test reads its data at a constant index, which llvmpipe does once
    // per SIMD group instead of once per lane (0.72x the instructions of a Cornell box pass,
    // docs/performance.md); each test is compiled in twice (nearest hit and shadow ray), so the
    // count is capped to keep compilation short.
    static constexpr int kMaxUnrolledShapes = 32;

    static ShaderFeatures all(); // the uber-shader: every model, map and meshes

    bool usesModel(MaterialType type) const { return (materialModels >> static_cast<int>(type)) & 1u; }
    bool hasLightKind(LightKind kind) const { return (lightKinds >> static_cast<int>(kind)) & 1u; }
    bool transmission() const;
    // Whether every feature of `other` is compiled into a program for these features.
    bool covers(const ShaderFeatures& other) const;
    bool operator==(const ShaderFeatures& other) const;
    bool operator!=(const ShaderFeatures& other) const { return !(*this == other); }
    bool operator<(const ShaderFeatures& other) const; // for use as a cache key

    // One line a feature: "materials: diffuse emitter", "lights: area point", ...
    std::string describe() const;
};

ShaderFeatures sceneFeatures(const Scene& scene);

} // namespace ptview
