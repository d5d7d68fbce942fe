#pragma once
// Simulate only what the scene calls for: the GLSL specialization that compiles in the features a
// scene uses (gpudata/SceneFeatures.h) and nothing else.
// Whole functions are chosen: the BSDF dispatch is generated with a case for each model used and
// only those models' files, and the environment and mesh queries come from a full or an empty
// variant of the same functions. The integrator and sampler become constants of the program.

#include <ptview/settings/DebugView.h>
#include <ptview/settings/Integrator.h>
#include <ptview/gpudata/SceneFeatures.h>
#include <ptview/settings/LightPaths.h>
#include <ptview/settings/SamplerMode.h>
#include <ptview/gl/ShaderAssembler.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ptview {

// Makes `assembler` build the path-tracing program for these features, integrator, sampler, view
// and light-path view: generated bsdf.glsl, light_kinds.glsl, shape_loops.glsl (when unrolled)
// and specialization.glsl, and the empty variant of each include whose feature the program lacks
// (kIncludeVariants in ShaderFeatures.cpp; the path recorder's hooks are always empty here).
void specializeShaders(ShaderAssembler& assembler, const ShaderFeatures& features, Integrator integrator,
                       SamplerMode sampler, DebugView view = DebugView::Radiance,
                       LightPaths lightPaths = LightPaths::All, bool edgeRays = true);
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
std::string generateMeshInstances(const ShaderFeatures& features);
std::string generateTextureSlots(const ShaderFeatures& features);

} // namespace ptview
