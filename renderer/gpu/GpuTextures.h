#pragma once
// The scene's textures on the GPU, within OpenGL 4.1 and one texture unit: every image is packed
// into an RGBA8 atlas (a 2D array texture: square pages of one size), and each texture has a
// record (GpuTextureRecord: page, origin, size, wrap, colour space, filter) that the shaders read
// from the materials' buffer. shaders/textures.glsl reads texels with texelFetch and filters
// and wraps them itself, so wrap modes work inside the atlas, sRGB is decoded per texel before
// filtering, and every GPU returns the same values.

#include <ptview/gl/GlObjects.h>
#include <ptview/gl/GlProgram.h>
#include <ptview/gpudata/GpuLayout.h>
#include <ptview/scene/Texture.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace ptview {

class TextureLimitError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Where each texture goes: pure CPU, testable without a context.
struct TextureAtlasLayout {
    int pageSize = 0;  // width = height of each page (a power of two)
    int pageCount = 0;
    std::vector<GpuTextureRecord> records; // per texture, in Scene::textures order
};

// Shelf packing, tallest first. Pages are the smallest power of two that holds the largest
// image, doubled (up to 4096 and maxSize) while the images' total area would need more pages.
// Throws TextureLimitError naming the texture's source when one is larger than maxSize on a
// side or the pages would exceed maxLayers.
TextureAtlasLayout packTextureAtlas(const std::vector<SceneTexture>& textures, int maxSize, int maxLayers);

class GpuTextures {
public:
    static constexpr const char* kSamplerName = "uTextureAtlas";
    static constexpr const char* kRecordStartName = "uTextureRecordStart";

    // Packs and uploads every texture (a 1x1 page when there are none). Throws
    // TextureLimitError past GL_MAX_TEXTURE_SIZE or GL_MAX_ARRAY_TEXTURE_LAYERS.
    void upload(const std::vector<SceneTexture>& textures);
    void bind(int unit) const;

    const std::vector<GpuTextureRecord>& records() const { return layout_.records; }
    std::size_t bytes() const; // GPU memory of the atlas
    // "3 textures, 12.0 MiB (2 pages of 2048^2), largest 2048x2048 (wood.png)"; "" when none.
    std::string describe() const;

private:
    GlTexture atlas_;
    TextureAtlasLayout layout_;
    std::size_t textureCount_ = 0;
    int largestWidth_ = 0;
    int largestHeight_ = 0;
    std::string largestSource_;
};

} // namespace ptview
