#pragma once
// Simulate only what the scene calls for: the features a scene uses (material models, kinds of
// light, environment map, meshes, a lens) and the GLSL specialization that compiles in those and
// nothing else.
// Whole functions are chosen: the BSDF dispatch is generated with a case for each model used and
// only those models' files, and the environment and mesh queries come from a full or an empty
// variant of the same functions. The integrator and sampler become constants of the program.

#include "DebugView.h"
#include "Integrator.h"
#include "LightKind.h"
#include "LightPaths.h"
#include "SamplerMode.h"
#include "Scene.h"
#include "ShaderAssembler.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

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
    bool textures = false;            // a material a shape uses has a texture (surface_textures.glsl)
    bool thinLens = false;            // the camera has an aperture (camera_thin_lens.glsl), else a pinhole
    bool normalMaps = false;          // ... a normal map (normal_map.glsl); implies textures
    bool alpha = false;               // ... alpha mode MASK or BLEND (surface_alpha.glsl); implies
                                      //   textures, since the coverage is read at texture coordinates
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

// Makes `assembler` build the path-tracing program for these features, integrator, sampler, view
// and light-path view: generated bsdf.glsl, light_kinds.glsl, shape_loops.glsl (when unrolled)
// and specialization.glsl, and the empty variant of each include whose feature the program lacks
// (kIncludeVariants in ShaderFeatures.cpp; the path recorder's hooks are always empty here).
void specializeShaders(ShaderAssembler& assembler, const ShaderFeatures& features, Integrator integrator,
                       SamplerMode sampler, DebugView view = DebugView::Radiance,
                       LightPaths lightPaths = LightPaths::All);
// The same for the path recorder's program (path_record.frag): the radiance view, with the
// recording hooks of path_recorder.glsl.
void specializePathRecorder(ShaderAssembler& assembler, const ShaderFeatures& features, Integrator integrator,
                            SamplerMode sampler, LightPaths lightPaths);
// The BSDF dispatch alone (probes that run BSDFs without a scene use every model).
void specializeBsdfs(ShaderAssembler& assembler, const ShaderFeatures& features);

// For the tests that hold the shader folder to the generator: each row of the table of includes
// with an empty variant, and what bsdf.glsl and light_kinds.glsl are generated as (shaders/ holds
// both as generated for ShaderFeatures::all()).
struct IncludeVariantFiles {
    std::string include;
    std::string emptyVariant;
};
std::vector<IncludeVariantFiles> includeVariantFiles();
std::string generateBsdfDispatch(const ShaderFeatures& features);
std::string generateLightKinds(const ShaderFeatures& features);

} // namespace ptview
