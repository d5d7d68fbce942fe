#pragma once
// The sRGB decode of an 8-bit channel (IEC 61966-2-1) as a table of its 256 values, for the
// shaders (srgb_decode_table.glsl, read by textures.glsl): the exact value of each byte rounded
// once to float. llvmpipe evaluated pow() per channel of every texel read, on every lookup, sRGB
// or not (both sides of a branch run for a SIMD group); a table read is cheaper and exact.

#include <cstdint>
#include <string>

namespace ptview {

// The linear value of sRGB code value byte / 255, computed in double and rounded to float.
float srgbByteToLinear(std::uint8_t byte);

// "const float kSrgbToLinear[256] = float[256](...);" with every value written so that it reads
// back as the same float.
std::string srgbDecodeTableGlsl();

} // namespace ptview
