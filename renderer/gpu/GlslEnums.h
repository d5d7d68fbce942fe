#pragma once
// The GLSL that C++ owns, generated from the C++ so the two sides cannot disagree: the shaders
// name these values (kIntegratorMis, kLightQuad, kMaterialTexels, uSeed, ...) and never spell
// them. Three includes come from this layer:
//   "enums.glsl":          the constants of the enum tables (integrators, samplers, debug views,
//                          tone mappers, light kinds, material types, light paths) and the few
//                          numbers both sides use (kSolidAngleSamplingMaxDistance);
//   "gpu_layout.glsl":     texels per record of the scene's buffers, the BVH stack depth and the
//                          primitive kinds (GpuLayout.h, GpuMeshes.h, SurfaceHit.h, Bvh.h);
//   "frame_uniforms.glsl": the uniform block FrameBlock, from kFrameBlockFields (GpuLayout.h).
// The layers above generate their own the same way (PathRecorder.h: "recorded_path.glsl",
// WarpProbe.h: "warp_ids.glsl"). Each has a copy in shaders/ for readers; GeneratedGlslTest
// keeps the copies current, and EnumTableTest fails when a shader defines a generated name itself.

#include <ptview/gl/ShaderAssembler.h>

#include <string>

namespace ptview {

// The text of "enums.glsl".
std::string glslEnumConstants();
// The text of "gpu_layout.glsl".
std::string glslLayoutConstants();
// The text of "frame_uniforms.glsl".
std::string glslFrameBlock();

// Makes `assembler` serve the three includes above and srgb_decode_table.glsl (SrgbDecodeTable.h);
// every program that includes a file naming their constants needs it (specializeShaders and
// specializeBsdfs call it).
void addGeneratedGlsl(ShaderAssembler& assembler);

// "const int kName = 7; // comment\n": one line of a generated include.
std::string glslIntConstant(const std::string& name, long long value, const std::string& comment = "");
std::string glslUintConstant(const std::string& name, unsigned long long value, const std::string& comment = "");

} // namespace ptview
