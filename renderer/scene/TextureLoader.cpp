#include <ptview/scene/TextureLoader.h>

#include <ptview/io/ImageDecode.h>
#include <ptview/io/InputFile.h>
#include <ptview/scene/ReadScope.h>
#include <ptview/scene/Scene.h>

// ptview_scene does not link stb's include directory (only ptview_io decodes); its declarations
// are all the header check needs, and libstb is linked through ptview_io.
#include <stb/stb_image.h>

#include <chrono>
#include <set>

namespace ptview {
namespace {

std::string mebibytes(std::uint64_t bytes) {
    return std::to_string((bytes + kMiB - 1) / kMiB) + " MiB";
}

} // namespace

glm::ivec2 readImageSize(const std::string& bytes, const std::string& source) {
    auto fail = [&source](const std::string& reason) { return TextureError(source + ": " + reason); };
    if (bytes.empty()) throw fail("empty image file");
    if (bytes.size() > std::size_t(0x7fffffff)) throw fail("image too large to decode");
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), static_cast<int>(bytes.size()), &width,
                               &height, &channels))
        throw fail(std::string("cannot decode image (not a PNG or JPEG, or corrupt: ") + stbi_failure_reason() + ")");
    if (width < 1 || height < 1) throw fail("empty image");
    if (width > kMaxDecodedImageSize || height > kMaxDecodedImageSize)
        throw fail("image too large (" + std::to_string(width) + "x" + std::to_string(height) + "; at most " +
                   std::to_string(kMaxDecodedImageSize) + " on a side)");
    return {width, height};
}

std::uint64_t decodedBytes(glm::ivec2 size) {
    return std::uint64_t(std::max(size.x, 0)) * std::uint64_t(std::max(size.y, 0)) * 4;
}

std::uint64_t decodedTextureBytes(const Scene& scene) {
    std::set<const TextureImage*> counted;
    std::uint64_t total = 0;
    auto count = [&](const std::shared_ptr<const TextureImage>& image) {
        if (image && counted.insert(image.get()).second) total += decodedBytes({image->width, image->height});
    };
    for (const SceneTexture& texture : scene.textures) count(texture.image);
    for (const SceneMesh& mesh : scene.meshes) {
        if (!mesh.data) continue;
        for (const MeshMaterial& material : mesh.data->fileMaterials)
            for (const MeshTextureMap* map : {&material.diffuseMap, &material.emissionMap, &material.roughnessMap,
                                              &material.metallicMap, &material.normalMap})
                count(map->image);
    }
    return total;
}

void TextureBudget::charge(glm::ivec2 size, const std::string& source) {
    const std::uint64_t bytes = decodedBytes(size);
    if (bytes > limit_ || spent_ > limit_ - bytes)
        throw TextureError(source + ": a " + std::to_string(size.x) + "x" + std::to_string(size.y) + " image takes " +
                           mebibytes(bytes) + " decoded; with the " + mebibytes(spent_) +
                           " the scene's textures take already, that passes the limit of " + mebibytes(limit_) +
                           " for the textures of one scene (docs/scene-format.md, \"Limits\")");
    spent_ += bytes;
}

std::shared_ptr<const TextureImage> decodeTextureImage(const std::string& bytes, const std::string& source,
                                                       TextureBudget* budget) {
    const auto start = std::chrono::steady_clock::now();
    if (budget) budget->charge(readImageSize(bytes, source), source);
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

std::shared_ptr<const TextureImage> loadTextureImage(const std::filesystem::path& path, TextureBudget* budget) {
    return decodeTextureImage(readInputFileAs<TextureError>(path, kMaxTextureFileBytes, "image file"), path.string(), budget);
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

void TextureImageCache::reserve(const std::filesystem::path& path) {
    const std::filesystem::path key = resolvedPath(path);
    if (reserved_.count(key)) return;
    const std::string bytes = readInputFileAs<TextureError>(path, kMaxTextureFileBytes, "image file");
    const glm::ivec2 size = readImageSize(bytes, path.string());
    budget_.charge(size, path.string());
    reserved_[key] = size;
}

std::shared_ptr<const TextureImage> TextureImageCache::load(const std::filesystem::path& path) {
    const std::filesystem::path key = resolvedPath(path);
    auto found = images_.find(key);
    if (found != images_.end()) return found->second;
    const std::string bytes = readInputFileAs<TextureError>(path, kMaxTextureFileBytes, "image file");
    const glm::ivec2 size = readImageSize(bytes, path.string());
    // Charged again when the file was not reserved, or changed size since.
    auto reserved = reserved_.find(key);
    if (reserved == reserved_.end() || reserved->second != size) {
        budget_.charge(size, path.string());
        reserved_[key] = size;
    }
    auto image = decodeTextureImage(bytes, path.string());
    images_.emplace(key, image);
    return image;
}

} // namespace ptview
