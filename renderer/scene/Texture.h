#pragma once
// Textures as the scene model holds them: decoded 8-bit images with how to read them. The
// loaders (scene JSON, MTL, glTF) decode every image once when the scene loads, so the renderer
// never touches a file and a texture that does not decode is an error naming it at load time.
//
// Texture coordinates follow glTF's convention everywhere in the model: (0, 0) is the top-left
// corner of the image as its file stores it (the first row), u grows to the right and v down.
// OBJ counts v up from the bottom row, so the OBJ loader stores 1 - v.

#include <ptview/settings/EnumTable.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace ptview {

// How 8-bit values map to numbers: colours (base colour, emission) are sRGB-encoded and decoded
// to linear before filtering; data (roughness, metallic, normals, alpha) are read as value / 255.
enum class TextureColorSpace { Srgb, Linear };

// Outside [0, 1], as glTF's sampler says (and OBJ's -clamp): repeat, clamp to the edge texel,
// or repeat mirrored every other period.
enum class TextureWrap { Repeat, ClampToEdge, MirroredRepeat };

// The scene file's words (docs/scene-format.md); glTF numbers them (GL's enums), and the shaders'
// textures.glsl reads the constants.
inline const EnumTable<TextureWrap>& textureWrapNames() {
    static const EnumTable<TextureWrap> table = {
        {TextureWrap::Repeat, "repeat", nullptr, "", "kTextureWrapRepeat"},
        {TextureWrap::ClampToEdge, "clamp", "clamp to edge", "", "kTextureWrapClampToEdge"},
        {TextureWrap::MirroredRepeat, "mirror", "mirrored repeat", "", "kTextureWrapMirroredRepeat"},
    };
    return table;
}

// RGBA, 8 bits per channel, rows top first, as decoded from a PNG or JPEG (grey and grey-alpha
// images are expanded: R = G = B).
struct TextureImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba; // width * height * 4
    // How long decoding the file's bytes took (not reading them), for `ptview bench`'s split of
    // a scene's load time into parsing and image decoding.
    double decodeSeconds = 0.0;
};

struct SceneTexture {
    // Where it came from, for the panel and messages: a file, or for an image inside a glTF
    // buffer "model.glb#/images/3".
    std::string source;
    std::filesystem::path file; // the image file; empty when it is embedded
    TextureColorSpace colorSpace = TextureColorSpace::Srgb;
    TextureWrap wrapU = TextureWrap::Repeat;
    TextureWrap wrapV = TextureWrap::Repeat;
    // Bilinear between texel centres; false: nearest texel (glTF's NEAREST magnification).
    bool bilinear = true;
    std::shared_ptr<const TextureImage> image; // shared by textures of the same file
};

// One material input's texture: the input is factor x texture(uv * scale + offset). The channel
// read is fixed per input (docs/materials.md): RGB for colours, G for roughness, B for metallic,
// A for alpha (of the base colour texture), RGB for a tangent-space normal.
struct TextureSlot {
    int texture = -1; // into Scene::textures; -1: none, the factor alone
    glm::vec2 scale{1.0f};
    glm::vec2 offset{0.0f};

    bool used() const { return texture >= 0; }
};

} // namespace ptview
