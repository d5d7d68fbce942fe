#pragma once
// Runs a fragment program once per work item over a grid of texels and reads its RGBA32F outputs
// back: how the tests and tools run the product's GLSL functions (warps, samplers, BSDFs) on the
// GPU. Item i is texel (i % width, i / width); the program gets uWidth and uCount uniforms and
// its inputs as RGBA32F textures on units 0, 1, ... laid out the same way.

#include <ptview/gl/GlProgram.h>

#include <glm/glm.hpp>

#include <vector>

namespace ptview {

using ProbeData = std::vector<glm::vec4>;

// inputs[k] (count items each, or empty) go to texture unit k; returns outputCount arrays of
// count items. The program must be current-ready: its other uniforms set by the caller.
std::vector<ProbeData> runProbePass(const GlProgram& program, int count, const std::vector<ProbeData>& inputs,
                                    int outputCount);

} // namespace ptview
