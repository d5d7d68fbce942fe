#pragma once
// The GLSL constants of the enum tables (integrators, samplers, debug views, tone mappers, light
// kinds) and of the few numbers both sides use (kSolidAngleSamplingMaxDistance), generated from
// the C++ as the include "enums.glsl": the shaders name the values (kIntegratorMis, kLightQuad,
// ...) and never number them, so the two sides cannot disagree.

#include "ShaderAssembler.h"

#include <string>

namespace ptview {

// The text of "enums.glsl".
std::string glslEnumConstants();

// Makes `assembler` serve "enums.glsl"; every program that includes a file naming these
// constants needs it (specializeShaders and specializeBsdfs call it).
void addGlslEnums(ShaderAssembler& assembler);

} // namespace ptview
