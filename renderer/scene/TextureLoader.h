#pragma once
// Turning image files (or bytes from a glTF buffer) into SceneTextures: the one place every
// loader (scene JSON, MTL, glTF) decodes a texture, with the same checks and messages.
//
// What a scene may make us allocate for its textures is bounded before any pixel is decoded: an
// image's width and height come from its header (at most kMaxDecodedImageSize a side,
// ImageDecode.h), and the decoded RGBA8 bytes of all textures of one scene load add up to at most
// kMaxSceneTextureBytes (TextureBudget). docs/scene-format.md, "Limits", lists both.

#include <ptview/scene/Texture.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

namespace ptview {

struct Scene;

// what() reads "SOURCE: reason", on one line; the loaders rethrow it with their own place
// (the JSON pointer, the MTL line, the glTF path) in front or behind.
class TextureError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// An image file is at most this large on disk.
constexpr std::uintmax_t kMaxTextureFileBytes = std::uintmax_t(256) << 20;

// Decoded RGBA8 bytes of all the textures of one scene load (scene JSON textures, MTL maps, glTF
// images). 1 GiB holds one image of the largest size a GPU takes (16384 x 16384), or 64 maps of
// 2048 x 2048 (the shipped helmet has five), and keeps six small PNGs claiming 16384 x 16384 each
// from asking for 6 GiB.
constexpr std::uint64_t kMaxSceneTextureBytes = std::uint64_t(1) << 30;

// Width and height from an encoded image's header, without decoding a pixel. Throws TextureError
// ("SOURCE: reason") for bytes that are no PNG or JPEG, or a size over kMaxDecodedImageSize.
glm::ivec2 readImageSize(const std::string& bytes, const std::string& source);

// The decoded bytes of an image of `size`: what it will take in memory (and on the GPU).
std::uint64_t decodedBytes(glm::ivec2 size);
// What the scene's decoded images take already, each image once: its textures and its meshes'
// MTL maps. A loader adding to the scene starts its TextureBudget from it.
std::uint64_t decodedTextureBytes(const Scene& scene);

// The decoded bytes one scene load still may spend on textures. Charged with an image's size
// from its header before it is decoded.
class TextureBudget {
public:
    explicit TextureBudget(std::uint64_t alreadySpent = 0, std::uint64_t limit = kMaxSceneTextureBytes)
        : spent_(alreadySpent), limit_(limit) {}
    // Counts an image of `size` named `source`; throws TextureError naming it and the limit,
    // counting nothing, when that would pass the limit.
    void charge(glm::ivec2 size, const std::string& source);
    std::uint64_t spent() const { return spent_; }

private:
    std::uint64_t spent_;
    std::uint64_t limit_;
};

// Reads and decodes `path` (PNG or JPEG, 8 bits per channel; 16-bit PNGs are reduced to 8)
// into RGBA8. Throws TextureError naming the file. With a budget, the image's size is charged to
// it from the header before decoding.
std::shared_ptr<const TextureImage> loadTextureImage(const std::filesystem::path& path, TextureBudget* budget = nullptr);
// The same from bytes in memory; `source` names them ("model.glb#/images/3").
std::shared_ptr<const TextureImage> decodeTextureImage(const std::string& bytes, const std::string& source,
                                                       TextureBudget* budget = nullptr);

// A texture of the file `path` read as `colorSpace` with the given sampler. Throws TextureError.
SceneTexture loadTexture(const std::filesystem::path& path, TextureColorSpace colorSpace,
                         TextureWrap wrapU = TextureWrap::Repeat, TextureWrap wrapV = TextureWrap::Repeat,
                         bool bilinear = true);

// Decodes each file once per scene load: textures of the same file share one TextureImage
// (Texture.h), whatever their colour space or sampler. Every file is charged to one budget,
// once; a loader that reserves all its files before loading any refuses too much before it has
// decoded anything.
class TextureImageCache {
public:
    explicit TextureImageCache(std::uint64_t alreadySpent = 0) : budget_(alreadySpent) {}
    // Reads the file's header and charges its decoded size, without decoding. Throws TextureError.
    void reserve(const std::filesystem::path& path);
    // Throws TextureError.
    std::shared_ptr<const TextureImage> load(const std::filesystem::path& path);
    std::uint64_t spentBytes() const { return budget_.spent(); }

private:
    TextureBudget budget_;
    std::map<std::filesystem::path, glm::ivec2> reserved_; // by resolved path
    std::map<std::filesystem::path, std::shared_ptr<const TextureImage>> images_;
};

} // namespace ptview
