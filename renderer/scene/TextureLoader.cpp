#include "TextureLoader.h"

#include "ImageDecode.h"
#include "InputFile.h"

#include <chrono>

namespace ptview {

std::shared_ptr<const TextureImage> decodeTextureImage(const std::string& bytes, const std::string& source) {
    const auto start = std::chrono::steady_clock::now();
    ImageRgba8 decoded;
    try {
        decoded = decodeImageRgba8(bytes, source);
    } catch (const ImageDecodeError& e) {
        throw TextureError(e.what());
    }
    auto image = std::make_shared<TextureImage>();
    image->width = decoded.width;
    image->height = decoded.height;
    image->rgba = std::move(decoded.rgba);
    image->decodeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return image;
}

std::shared_ptr<const TextureImage> loadTextureImage(const std::filesystem::path& path) {
    return decodeTextureImage(readInputFileAs<TextureError>(path, kMaxTextureFileBytes, "image file"), path.string());
}

SceneTexture loadTexture(const std::filesystem::path& path, TextureColorSpace colorSpace, TextureWrap wrapU,
                         TextureWrap wrapV, bool bilinear) {
    SceneTexture texture;
    texture.source = path.string();
    texture.file = path;
    texture.colorSpace = colorSpace;
    texture.wrapU = wrapU;
    texture.wrapV = wrapV;
    texture.bilinear = bilinear;
    texture.image = loadTextureImage(path);
    return texture;
}

std::shared_ptr<const TextureImage> TextureImageCache::load(const std::filesystem::path& path) {
    std::error_code error;
    std::filesystem::path key = std::filesystem::weakly_canonical(path, error);
    if (error) key = path;
    auto found = images_.find(key);
    if (found != images_.end()) return found->second;
    auto image = loadTextureImage(path);
    images_.emplace(key, image);
    return image;
}

} // namespace ptview
