#pragma once
// A scene file as read from its JSON, before the files it names are: the model so far and the
// requests that the resolvers (SceneFileResolve.h) still have to answer with meshes, textures and
// glTF imports, each with the place in the document that made it, for errors.

#include <ptview/scene/Scene.h>
#include <ptview/scene/SceneJson.h>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ptview::sceneFile {

// A texture a material input names, decoded once the whole file is read (resolveTextures).
struct TextureRequest {
    std::size_t material;             // in Scene::materials
    TextureSlot Material::*slot;
    std::filesystem::path file;       // as written; resolved against the scene file's directory
    TextureColorSpace colorSpace;
    TextureWrap wrapU = TextureWrap::Repeat;
    TextureWrap wrapV = TextureWrap::Repeat;
    bool bilinear = true;
    Pointer at;                       // the "texture" key (or the input, when it is a bare path)
};

// How a mesh shape named its materials; resolved once the mesh file is read.
struct MeshMaterialRequest {
    std::size_t shape;
    Pointer at;
    std::optional<std::string> material;             // "material": every slot not named below
    std::vector<std::pair<std::string, std::string>> bySlot; // "materials": OBJ name -> scene material
};

// The scene as read from JSON, before its mesh files are: what parseScene still has to resolve.
struct SceneDraft {
    Scene scene;
    std::vector<Pointer> meshPlaces; // where each of scene.meshes was declared
    std::vector<MeshMaterialRequest> meshRequests;
    std::vector<TextureRequest> textureRequests;
    std::vector<Pointer> importPlaces; // where each of scene.imports was declared
    std::vector<const Json*> importOverrides; // each entry's "materials", or null; applied once the file is read
    std::vector<const Json*> importLightOverrides; // each entry's "lights", or null
};
} // namespace ptview::sceneFile
