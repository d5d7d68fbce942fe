#include "MaterialTextures.h"

#include "SceneLoader.h"
#include "TextureLoader.h"

#include <utility>

namespace ptview {

SceneTexture readTextureFile(const std::filesystem::path& file, TextureColorSpace colorSpace) {
    try {
        return loadTexture(file, colorSpace);
    } catch (const TextureError& e) {
        throw SceneError(e.what()); // "FILE: reason"
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
