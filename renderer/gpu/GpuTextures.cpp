#include <ptview/gpu/GpuTextures.h>

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace ptview {
namespace {

int powerOfTwoAtLeast(int n) {
    int p = 1;
    while (p < n) p *= 2;
    return p;
}

// Shelves of the tallest remaining image, left to right, page after page. False when some image
// does not fit a page of this size (it never happens when the page holds the largest image).
bool shelfPack(const std::vector<SceneTexture>& textures, const std::vector<std::size_t>& order, int pageSize,
               TextureAtlasLayout& layout) {
    layout.pageSize = pageSize;
    layout.pageCount = textures.empty() ? 0 : 1;
    layout.records.assign(textures.size(), GpuTextureRecord{});
    int x = 0, y = 0, shelfHeight = 0, page = 0;
    for (std::size_t index : order) {
        const TextureImage& image = *textures[index].image;
        if (image.width > pageSize || image.height > pageSize) return false;
        if (x + image.width > pageSize) { // next shelf
            x = 0;
            y += shelfHeight;
            shelfHeight = 0;
        }
        if (y + image.height > pageSize) { // next page
            ++page;
            x = y = shelfHeight = 0;
        }
        const SceneTexture& texture = textures[index];
        GpuTextureRecord& record = layout.records[index];
        record.layer = float(page);
        record.originX = float(x);
        record.originY = float(y);
        record.width = float(image.width);
        record.height = float(image.height);
        record.wrapU = float(static_cast<int>(texture.wrapU));
        record.wrapV = float(static_cast<int>(texture.wrapV));
        record.flags = (texture.colorSpace == TextureColorSpace::Srgb ? 1.0f : 0.0f) + (texture.bilinear ? 2.0f : 0.0f);
        x += image.width;
        shelfHeight = std::max(shelfHeight, image.height);
        layout.pageCount = page + 1;
    }
    return true;
}

} // namespace

TextureAtlasLayout packTextureAtlas(const std::vector<SceneTexture>& textures, int maxSize, int maxLayers) {
    int largest = 1;
    double area = 0.0;
    for (const SceneTexture& texture : textures) {
        if (!texture.image) throw TextureLimitError(texture.source + ": texture has no image");
        const TextureImage& image = *texture.image;
        if (image.width > maxSize || image.height > maxSize)
            throw TextureLimitError(texture.source + ": texture is " + std::to_string(image.width) + "x" +
                                    std::to_string(image.height) + ", larger than this GPU's limit of " +
                                    std::to_string(maxSize) + " on a side");
        largest = std::max({largest, image.width, image.height});
        area += double(image.width) * double(image.height);
    }
    std::vector<std::size_t> order(textures.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return textures[a].image->height > textures[b].image->height;
    });
    int pageSize = std::min(powerOfTwoAtLeast(largest), maxSize);
    while (pageSize * 2 <= std::min(4096, maxSize) && area > double(pageSize) * double(pageSize)) pageSize *= 2;
    TextureAtlasLayout layout;
    shelfPack(textures, order, pageSize, layout); // pageSize >= largest: always fits
    if (layout.pageCount > maxLayers) {
        // Name the first texture that lands beyond the last layer.
        std::string source;
        for (std::size_t i = 0; i < textures.size() && source.empty(); ++i)
            if (layout.records[i].layer >= float(maxLayers)) source = textures[i].source;
        throw TextureLimitError(source + ": the textures need " + std::to_string(layout.pageCount) + " atlas pages of " +
                                std::to_string(pageSize) + "^2, more than this GPU's " + std::to_string(maxLayers) +
                                " array layers");
    }
    return layout;
}

void GpuTextures::upload(const std::vector<SceneTexture>& textures) {
    GLint maxSize = 0, maxLayers = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
    layout_ = packTextureAtlas(textures, maxSize, maxLayers);
    textureCount_ = textures.size();
    largestWidth_ = largestHeight_ = 0;
    largestSource_.clear();
    for (const SceneTexture& texture : textures) {
        if (std::size_t(texture.image->width) * std::size_t(texture.image->height) >
            std::size_t(largestWidth_) * std::size_t(largestHeight_)) {
            largestWidth_ = texture.image->width;
            largestHeight_ = texture.image->height;
            largestSource_ = texture.source;
        }
    }
    if (atlas_.id() == 0) atlas_ = createTexture();
    const int size = std::max(layout_.pageSize, 1);
    const int layers = std::max(layout_.pageCount, 1);
    glBindTexture(GL_TEXTURE_2D_ARRAY, atlas_.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA8, size, size, layers, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    for (std::size_t i = 0; i < textures.size(); ++i) {
        const GpuTextureRecord& record = layout_.records[i];
        const TextureImage& image = *textures[i].image;
        glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, GLint(record.originX), GLint(record.originY), GLint(record.layer),
                        image.width, image.height, 1, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    }
    // texelFetch only: no sampler state is used, but an incomplete texture would read as black.
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
}

void GpuTextures::bind(int unit) const {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D_ARRAY, atlas_.id());
}

std::size_t GpuTextures::bytes() const {
    return textureCount_ == 0 ? 0
                              : std::size_t(layout_.pageSize) * std::size_t(layout_.pageSize) * 4 * std::size_t(layout_.pageCount);
}

std::string GpuTextures::describe() const {
    if (textureCount_ == 0) return "";
    char line[512];
    std::snprintf(line, sizeof line, "%zu texture%s, %.1f MiB (%d page%s of %d^2), largest %dx%d (%s)", textureCount_,
                  textureCount_ == 1 ? "" : "s", double(bytes()) / double(1 << 20), layout_.pageCount,
                  layout_.pageCount == 1 ? "" : "s", layout_.pageSize, largestWidth_, largestHeight_, largestSource_.c_str());
    return line;
}

} // namespace ptview
