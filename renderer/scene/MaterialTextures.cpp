#include "MaterialTextures.h"

#include "ImageDecode.h"
#include "InputFile.h"
#include "SceneLoader.h"

#include <string>
#include <utility>

namespace ptview {

namespace {
// A compressed 16384^2 RGBA image (the largest that decodes, ImageDecode.h) stays well below this.
constexpr std::uintmax_t kMaxTextureFileBytes = 1024 * kMiB;
} // namespace

SceneTexture readTextureFile(const std::filesystem::path& file, TextureColorSpace colorSpace) {
    std::string bytes;
    try {
        bytes = readInputFile(file, kMaxTextureFileBytes, "texture");
    } catch (const InputFileError& e) {
        throw SceneError(e.what());
    }
    try {
        ImageRgba8 rgba = decodeImageRgba8(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
        auto image = std::make_shared<TextureImage>();
        image->width = rgba.width;
        image->height = rgba.height;
        image->rgba = std::move(rgba.rgba);
        SceneTexture texture;
        texture.source = file.string();
        texture.file = file;
        texture.colorSpace = colorSpace;
        texture.image = std::move(image);
        return texture;
    } catch (const ImageDecodeError& e) {
        throw SceneError(file.string() + ": " + e.what());
    }
}

void setMaterialTexture(Scene& scene, Material& material, const MaterialTextureInput& input,
                        const std::filesystem::path& file) {
    if (file.empty()) {
        (material.*input.slot).texture = -1;
        return;
    }
    SceneTexture texture = readTextureFile(file, input.colorSpace); // throws before anything changes
    (material.*input.slot).texture = static_cast<int>(scene.textures.size());
    scene.textures.push_back(std::move(texture));
}

} // namespace ptview
