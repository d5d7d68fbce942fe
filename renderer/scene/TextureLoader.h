#pragma once
// Turning image files (or bytes from a glTF buffer) into SceneTextures: the one place every
// loader (scene JSON, MTL, glTF) decodes a texture, with the same checks and messages.

#include "Texture.h"

#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

namespace ptview {

// what() reads "SOURCE: reason", on one line; the loaders rethrow it with their own place
// (the JSON pointer, the MTL line, the glTF path) in front or behind.
class TextureError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// An image file is at most this large on disk.
constexpr std::uintmax_t kMaxTextureFileBytes = std::uintmax_t(256) << 20;

// Reads and decodes `path` (PNG or JPEG, 8 bits per channel; 16-bit PNGs are reduced to 8)
// into RGBA8. Throws TextureError naming the file.
std::shared_ptr<const TextureImage> loadTextureImage(const std::filesystem::path& path);
// The same from bytes in memory; `source` names them ("model.glb#/images/3").
std::shared_ptr<const TextureImage> decodeTextureImage(const std::string& bytes, const std::string& source);

// A texture of the file `path` read as `colorSpace` with the given sampler. Throws TextureError.
SceneTexture loadTexture(const std::filesystem::path& path, TextureColorSpace colorSpace,
                         TextureWrap wrapU = TextureWrap::Repeat, TextureWrap wrapV = TextureWrap::Repeat,
                         bool bilinear = true);

// Decodes each file once per scene load: textures of the same file share one TextureImage
// (Texture.h), whatever their colour space or sampler.
class TextureImageCache {
public:
    std::shared_ptr<const TextureImage> load(const std::filesystem::path& path);

private:
    std::map<std::filesystem::path, std::shared_ptr<const TextureImage>> images_;
};

} // namespace ptview
