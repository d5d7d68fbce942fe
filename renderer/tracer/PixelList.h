#pragma once
// The pixels adaptive sampling still samples, packed for the compute backend (pathtrace.comp):
// a pass over an image whose pixels mostly stopped dispatches one invocation per pixel still
// sampled rather than one per pixel, so that stopped pixels leave no SIMD lane idle and no
// workgroup with little to do beside a full one (docs/sampling.md, "Packed passes").

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace ptview {

// stopped: one flag per pixel, rows top first. Returns the others, each as x | y << 16 in GL
// window coordinates (rows from the bottom), 4x2 blocks of pixels at a time, blocks in rows:
// llvmpipe runs 8 consecutive invocations as one SIMD group, and neighbours walk much the same
// nodes (pathtrace.comp's pixelInWorkGroup orders a full tile the same way).
std::vector<std::uint32_t> packedPixelsStillSampled(const std::vector<std::uint8_t>& stopped, glm::ivec2 size);

} // namespace ptview
