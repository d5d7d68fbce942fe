#pragma once
// A material's texture inputs by name, and an image file read as a scene texture: what the
// viewer's Materials panel and the script's `set-material NAME.INPUT-texture PATH|none` read and
// change (one table for both). No OpenGL.

#include <ptview/scene/Scene.h>
#include <ptview/scene/Texture.h>

#include <filesystem>

namespace ptview {

// A principled material's texture input: where its slot is and how its texels are read.
struct MaterialTextureInput {
    const char* name;  // "base-color": the script's field is "base-color-texture"
    const char* label; // the panel's
    TextureSlot Material::*slot;
    TextureColorSpace colorSpace;
};

inline const MaterialTextureInput kMaterialTextureInputs[] = {
    {"base-color", "base colour", &Material::baseColorTexture, TextureColorSpace::Srgb},
    {"roughness", "roughness (G)", &Material::roughnessTexture, TextureColorSpace::Linear},
    {"metallic", "metallic (B)", &Material::metallicTexture, TextureColorSpace::Linear},
    {"normal", "normal map", &Material::normalTexture, TextureColorSpace::Linear},
    {"emission", "emission", &Material::emissionTexture, TextureColorSpace::Srgb},
};

// How the texels of the input in `slot` are read: the one place that says colours are sRGB and
// data linear, for every loader (scene JSON, MTL, glTF) and the editors.
inline TextureColorSpace colorSpaceOf(TextureSlot Material::*slot) {
    for (const MaterialTextureInput& input : kMaterialTextureInputs)
        if (input.slot == slot) return input.colorSpace;
    return TextureColorSpace::Linear;
}

// Gives the input the image in `file` (a new scene texture, appended), or no texture when `file`
// is empty; the slot's scale and offset are kept. Only principled materials read textures: the
// callers make a material principled first (the panel's type change). Throws SceneError naming
// the file, and then leaves the material and the scene as they were.
void setMaterialTexture(Scene& scene, Material& material, const MaterialTextureInput& input,
                        const std::filesystem::path& file);

} // namespace ptview
