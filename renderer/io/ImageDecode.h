#pragma once
// Decoding 8-bit PNG and JPEG images (through stb_image) from bytes already in memory: the
// texture loader reads files with readInputFile's checks, and glTF hands over its buffers.

#include <ptview/io/Image.h>

#include <stdexcept>
#include <string>

namespace ptview {

// what() reads "SOURCE: reason", on one line.
class ImageDecodeError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The largest width or height accepted; the GPU's own limit is checked when the texture is
// uploaded (GpuTextures).
constexpr int kMaxDecodedImageSize = 16384;

// RGBA8, rows top first as the file stores them; grey becomes R = G = B, a missing alpha 255.
// 16-bit PNGs are reduced to 8 bits (stb's rounding). `source` names the image in messages.
// Throws ImageDecodeError for bytes that are no PNG/JPEG, a truncated or corrupt image, a size
// over kMaxDecodedImageSize, or no memory for the pixels.
ImageRgba8 decodeImageRgba8(const std::string& bytes, const std::string& source);

} // namespace ptview
