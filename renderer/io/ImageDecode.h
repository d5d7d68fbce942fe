#pragma once
// Decoding 8-bit PNG and JPEG images held in memory (textures), with stb_image. A file claiming a
// size that no texture can have is refused from its header, before any pixel memory is taken.

#include "Image.h"

#include <cstddef>
#include <stdexcept>

namespace ptview {

// what() is the reason alone ("not a PNG or JPEG image (stb: ...)"); the caller names the file.
class ImageDecodeError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A side longer than this is refused before decoding: GPUs' texture limits are 16384 or 32768,
// and one such RGBA8 image already takes 1 GiB.
inline constexpr int kMaxDecodedImageSide = 16384;

// RGBA, rows top first; grey and grey-alpha images are expanded (R = G = B), RGB gets A = 255,
// and 16-bit PNGs keep their high byte. Throws ImageDecodeError.
ImageRgba8 decodeImageRgba8(const unsigned char* bytes, std::size_t size);

} // namespace ptview
