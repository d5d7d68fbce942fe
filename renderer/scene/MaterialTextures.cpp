#include <ptview/scene/MaterialTextures.h>

#include <ptview/scene/SceneError.h>
#include <ptview/scene/TextureLoader.h>

#include <utility>

namespace ptview {

void setMaterialTexture(Scene& scene, Material& material, const MaterialTextureInput& input,
                        const std::filesystem::path& file) {
    if (file.empty()) {
        (material.*input.slot).texture = -1;
        return;
    }
    SceneTexture texture;
    try {
        // Decoded (TextureLoader.h), repeating and bilinear, before anything changes.
        texture = loadTexture(file, input.colorSpace);
    } catch (const TextureError& e) {
        throw SceneError(e.what()); // "FILE: reason"
    }
    (material.*input.slot).texture = static_cast<int>(scene.textures.size());
    scene.textures.push_back(std::move(texture));
}

} // namespace ptview
