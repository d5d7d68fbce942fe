#include <ptview/scene/SceneFileResolve.h>

#include <ptview/scene/GltfLoader.h>
#include <ptview/scene/MaterialReader.h>
#include <ptview/scene/MaterialTextures.h>
#include <ptview/scene/ObjLoader.h>
#include <ptview/scene/ScenePartsReader.h>
#include <ptview/scene/SceneFileReaders.h>
#include <ptview/scene/TextureLoader.h>

#include <algorithm>
#include <memory>
#include <optional>

namespace ptview::sceneFile {
namespace {

// A texture slot for an MTL map: one scene texture per image, colour space and wrap, however
// many materials use it; the map's -s/-o in the slot. A map without an image (missing or not
// decoded, already warned about) leaves the slot empty: the factor alone.
TextureSlot textureSlotFromMap(const MeshTextureMap& map, TextureColorSpace colorSpace, Scene& scene) {
    TextureSlot slot;
    if (!map.image) return slot;
    const TextureWrap wrap = map.clamp ? TextureWrap::ClampToEdge : TextureWrap::Repeat;
    slot.scale = map.scale;
    slot.offset = map.offset;
    for (std::size_t i = 0; i < scene.textures.size(); ++i) {
        const SceneTexture& texture = scene.textures[i];
        if (texture.image == map.image && texture.colorSpace == colorSpace && texture.wrapU == wrap && texture.wrapV == wrap) {
            slot.texture = static_cast<int>(i);
            return slot;
        }
    }
    SceneTexture texture;
    texture.source = map.file.string();
    texture.file = map.file;
    texture.colorSpace = colorSpace;
    texture.wrapU = texture.wrapV = wrap;
    texture.image = map.image;
    slot.texture = static_cast<int>(scene.textures.size());
    scene.textures.push_back(std::move(texture));
    return slot;
}

// An MTL entry with texture maps as a principled material (docs/scene-format.md, "MTL
// materials"): Kd x map_Kd the base colour, Ke x map_Ke the emission, Pr x map_Pr the roughness
// (without Pr, 1 with a map, else from Ns as for plastic), Pm x map_Pm the metallic (without Pm,
// 1 with a map, else 0), norm or map_Bump
// the normal map (-bm its scale), d the alpha (blended below 1), illum 4, 6 or 7 full transmission.
Material principledFromMeshFile(const MeshMaterial& source, float roughnessFromNs, Scene& scene) {
    Material material;
    material.type = MaterialType::Principled;
    material.color = glm::clamp(source.diffuse, 0.0f, 1.0f);
    // A map multiplies its factor; without Pr or Pm a map that loaded has the factor 1, so that it
    // gives the value (a metallic factor of 0 would make map_Pm do nothing).
    material.roughness = std::clamp(source.roughness.value_or(source.roughnessMap.image ? 1.0f : roughnessFromNs), 0.0f, 1.0f);
    material.metallic = std::clamp(source.metallic.value_or(source.metallicMap.image ? 1.0f : 0.0f), 0.0f, 1.0f);
    // tinyobjloader's Ni is 1 when the entry leaves it out, and exporters write 1 for "not set":
    // an index of 1 would give a dielectric no reflection at all.
    material.ior = source.ior > 1.0f ? std::min(source.ior, 4.0f) : 1.5f;
    material.alpha = std::clamp(source.dissolve, 0.0f, 1.0f);
    material.alphaMode = material.alpha < 1.0f ? AlphaMode::Blend : AlphaMode::Opaque;
    if (source.illum == 4 || source.illum == 6 || source.illum == 7) material.transmission = 1.0f;
    material.normalScale = source.normalMap.bumpMultiplier;
    material.baseColorTexture = textureSlotFromMap(source.diffuseMap, colorSpaceOf(&Material::baseColorTexture), scene);
    material.emissionTexture = textureSlotFromMap(source.emissionMap, colorSpaceOf(&Material::emissionTexture), scene);
    material.roughnessTexture = textureSlotFromMap(source.roughnessMap, colorSpaceOf(&Material::roughnessTexture), scene);
    material.metallicTexture = textureSlotFromMap(source.metallicMap, colorSpaceOf(&Material::metallicTexture), scene);
    material.normalTexture = textureSlotFromMap(source.normalMap, colorSpaceOf(&Material::normalTexture), scene);
    return material;
}

// A scene material made from a mesh file's own (MTL) material, for slots the scene file does
// not map: the closest of our models, named "MESH/NAME" so it shows as the mesh's. An entry
// with texture maps is principled; its textures are added to the scene.
Material materialFromMeshFile(const std::string& meshName, const MeshMaterial& source, Scene& scene) {
    // Phong exponent to roughness: alpha = sqrt(2 / (Ns + 2)) and alpha = roughness^2.
    const float roughnessFromNs = std::sqrt(std::sqrt(2.0f / (std::max(source.shininess, 0.0f) + 2.0f)));
    if (source.hasTextureMaps()) {
        Material material = principledFromMeshFile(source, roughnessFromNs, scene);
        material.name = meshName + "/" + source.name;
        material.radiance = glm::clamp(source.emission, 0.0f, kMaxRadiance);
        return material;
    }
    Material material;
    material.name = meshName + "/" + source.name;
    glm::vec3 diffuse = glm::clamp(source.diffuse, 0.0f, 1.0f);
    glm::vec3 specular = glm::clamp(source.specular, 0.0f, 1.0f);
    float specularLevel = std::max(specular.r, std::max(specular.g, specular.b));
    float diffuseLevel = std::max(diffuse.r, std::max(diffuse.g, diffuse.b));
    const float roughness = roughnessFromNs;
    if (source.dissolve < 1.0f || source.illum == 4 || source.illum == 6 || source.illum == 7) {
        material.type = MaterialType::Glass;
        material.color = glm::vec3(1.0f);
        material.ior = std::clamp(source.ior, 1.0f, 4.0f);
    } else if (specularLevel > 0.0f && diffuseLevel <= 0.01f) {
        material.type = MaterialType::Metal;
        material.color = specular;
        material.roughness = roughness;
    } else if (specularLevel > 0.0f) {
        material.type = MaterialType::Plastic;
        material.color = diffuse;
        material.ior = 1.5f;
        material.roughness = roughness;
    } else {
        material.type = MaterialType::Diffuse;
        material.color = diffuse;
    }
    // Clamped to the bound a scene file's radiance has (SceneRanges.h), as the colours above are to
    // [0, 1]: "Ke 1e20" in an MTL is no more renderable than in a scene file.
    material.radiance = glm::clamp(source.emission, 0.0f, kMaxRadiance);
    return material;
}

} // namespace

// Reads each mesh file once and gives every slot of every mesh shape a scene material: the
// shape's "materials" entry for it, else its "material", else the scene material of the same
// name, else one made from the mesh file's own definition.
void resolveMeshes(SceneDraft& draft, const std::filesystem::path& sceneFile, const ReadScope& scope) {
    Scene& scene = draft.scene;
    TextureBudget textureBudget(decodedTextureBytes(scene)); // every mesh's MTL maps together
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        SceneMesh& mesh = scene.meshes[m];
        if (mesh.file.is_relative()) mesh.file = sceneFile.parent_path() / mesh.file;
        if (std::optional<std::string> refusal = scope.refusal(mesh.file)) fail(draft.meshPlaces[m], *refusal);
        MeshLoadReport report;
        try {
            mesh.data = std::make_shared<const TriangleMesh>(loadObjMesh(mesh.file, &report, scope, &textureBudget));
        } catch (const MeshError& error) {
            // The mesh's own error names its file and line; say which scene entry wanted it.
            fail(draft.meshPlaces[m], error.what());
        }
        scene.warnings.insert(scene.warnings.end(), report.warnings.begin(), report.warnings.end());
    }
    for (const MeshMaterialRequest& request : draft.meshRequests) {
        Shape& shape = scene.shapes[request.shape];
        const SceneMesh& mesh = scene.meshes[static_cast<std::size_t>(shape.mesh)];
        const TriangleMesh& data = *mesh.data;
        std::vector<bool> slotUsed(data.materialSlots.size(), false);
        for (const MeshTriangle& triangle : data.triangles) slotUsed[static_cast<std::size_t>(triangle.materialSlot)] = true;
        for (const auto& [slotName, target] : request.bySlot) {
            if (std::find(data.materialSlots.begin(), data.materialSlots.end(), slotName) == data.materialSlots.end())
                fail(request.at / "materials" / slotName,
                     "the mesh \"" + mesh.name + "\" has no material slot \"" + slotName + "\" (no usemtl of that name)");
        }
        shape.slotMaterials.assign(data.materialSlots.size(), -1);
        for (std::size_t slot = 0; slot < data.materialSlots.size(); ++slot) {
            const std::string& slotName = data.materialSlots[slot];
            int material = -1;
            for (const auto& [name, target] : request.bySlot)
                if (name == slotName) material = findMaterial(scene.materials, target);
            if (material < 0 && request.material) material = findMaterial(scene.materials, *request.material);
            if (material < 0 && !slotName.empty()) material = findMaterial(scene.materials, slotName);
            if (material < 0 && !slotName.empty()) {
                auto own = std::find_if(data.fileMaterials.begin(), data.fileMaterials.end(),
                                        [&](const MeshMaterial& candidate) { return candidate.name == slotName; });
                if (own != data.fileMaterials.end()) {
                    const std::string madeName = mesh.name + "/" + own->name;
                    material = findMaterial(scene.materials, madeName);
                    if (material < 0) {
                        material = static_cast<int>(scene.materials.size());
                        scene.materials.push_back(materialFromMeshFile(mesh.name, *own, scene));
                    }
                }
            }
            if (material < 0 && slotUsed[slot])
                fail(request.at / "material",
                     slotName.empty() ? "missing: the mesh \"" + mesh.name + "\" has faces without a material (usemtl)"
                                      : "missing: nothing gives a material for the mesh's \"" + slotName +
                                            "\" faces (add \"materials\": {\"" + slotName + "\": ...})");
            shape.slotMaterials[slot] = std::max(material, 0);
        }
    }
}

// Decodes every texture the materials name, each file once (TextureLoader.h), relative to the
// scene file; textures of the same file and sampler are one Scene::textures entry. Every file's
// size is charged to the scene's texture budget from its header before any is decoded.
void resolveTextures(const std::vector<TextureRequest>& requests, const std::filesystem::path& sceneFile,
                     const ReadScope& scope, Scene& scene) {
    TextureImageCache cache(decodedTextureBytes(scene));
    auto fileOf = [&](const TextureRequest& request) {
        return request.file.is_relative() ? sceneFile.parent_path() / request.file : request.file;
    };
    for (const TextureRequest& request : requests) {
        std::filesystem::path file = fileOf(request);
        if (std::optional<std::string> refusal = scope.refusal(file)) fail(request.at, *refusal);
        try {
            cache.reserve(file);
        } catch (const TextureError& error) {
            fail(request.at, error.what());
        }
    }
    for (const TextureRequest& request : requests) {
        std::filesystem::path file = fileOf(request);
        int index = -1;
        for (std::size_t t = 0; t < scene.textures.size() && index < 0; ++t) {
            const SceneTexture& known = scene.textures[t];
            if (known.file == file && known.colorSpace == request.colorSpace && known.wrapU == request.wrapU &&
                known.wrapV == request.wrapV && known.bilinear == request.bilinear)
                index = static_cast<int>(t);
        }
        if (index < 0) {
            SceneTexture texture;
            texture.source = file.string();
            texture.file = file;
            texture.colorSpace = request.colorSpace;
            texture.wrapU = request.wrapU;
            texture.wrapV = request.wrapV;
            texture.bilinear = request.bilinear;
            try {
                texture.image = cache.load(file);
            } catch (const TextureError& error) {
                fail(request.at, error.what());
            }
            index = static_cast<int>(scene.textures.size());
            scene.textures.push_back(std::move(texture));
        }
        (scene.materials[request.material].*request.slot).texture = index;
    }
}

namespace {

// The error for an override whose key names none of the parts (materials, lights) a glTF file made,
// listing a few of their names.
template <typename Part>
[[noreturn]] void failNotInFile(const Pointer& at, const char* kind, const SceneImport& entry, const std::vector<Part>& parts) {
    std::string names;
    for (std::size_t i = 0; i < parts.size() && i < 4; ++i) names += (names.empty() ? "" : ", ") + ("\"" + parts[i].name + "\"");
    if (parts.size() > 4) names += ", ...";
    fail(at, std::string("no ") + kind + " of " + entry.file.filename().string() + " has this name (" +
                 (names.empty() ? "it has none" : "it has " + names) + ")");
}

// An entry's "materials": each key names a material the file made (in scene.materials from
// `first` on), its value an override of it (readMaterial with a base). Texture files the overrides
// name become requests.
void applyMaterialOverrides(const Json& overrides, const Pointer& at, const SceneImport& entry, std::size_t first,
                            Scene& scene, std::vector<TextureRequest>& textures) {
    for (auto it = overrides.begin(); it != overrides.end(); ++it) {
        int found = findMaterial(scene.materials, it.key());
        if (found < static_cast<int>(first)) failNotInFile(at / it.key(), "material", entry, entry.fileMaterials); // -1: none at all
        Material& material = scene.materials[static_cast<std::size_t>(found)];
        const Material file = material;
        material = readMaterial(file.name, it.value(), at / it.key(), static_cast<std::size_t>(found), textures, &file);
    }
}

// An entry's "lights": each key names a light the file made (in scene.lights from `first` on), its
// value the whole light in the syntax of "lights" but for its name, which the key gives.
void applyLightOverrides(const Json& overrides, const Pointer& at, const SceneImport& entry, int importIndex,
                         std::size_t first, Scene& scene) {
    for (auto it = overrides.begin(); it != overrides.end(); ++it) {
        auto found = std::find_if(scene.lights.begin() + static_cast<std::ptrdiff_t>(first), scene.lights.end(),
                                  [&](const Light& light) { return light.name == it.key(); });
        if (found == scene.lights.end()) failNotInFile(at / it.key(), "light", entry, entry.fileLights);
        if (it.value().is_object() && it.value().contains("name"))
            fail(at / it.key() / "name", "the key names the light it overrides; a name is not allowed here");
        Light light = readLight(it.value(), at / it.key(), static_cast<std::size_t>(found - scene.lights.begin()));
        light.name = it.key();
        light.importedFrom = importIndex;
        *found = light;
    }
}

} // namespace

// Appends each glTF file the scene places, after the scene's own parts, so that their indices
// (and the file's own order) are those of the file, and applies the entry's material overrides.
void resolveImports(SceneDraft& draft, const std::filesystem::path& sceneFile, const ReadScope& scope) {
    Scene& scene = draft.scene;
    std::vector<TextureRequest> overrideTextures;
    for (std::size_t i = 0; i < scene.imports.size(); ++i) {
        SceneImport& entry = scene.imports[i];
        if (entry.file.is_relative()) entry.file = sceneFile.parent_path() / entry.file;
        if (std::optional<std::string> refusal = scope.refusal(entry.file)) fail(draft.importPlaces[i], *refusal);
        const std::size_t first = scene.materials.size();
        const std::size_t firstLight = scene.lights.size();
        try {
            appendGltf(entry.file, entry.transform.objectToWorld(), static_cast<int>(i), scene, scope);
        } catch (const SceneError& error) {
            fail(draft.importPlaces[i], error.what());
        }
        entry.fileMaterials.assign(scene.materials.begin() + static_cast<std::ptrdiff_t>(first), scene.materials.end());
        entry.fileLights.assign(scene.lights.begin() + static_cast<std::ptrdiff_t>(firstLight), scene.lights.end());
        if (const Json* overrides = draft.importLightOverrides[i])
            applyLightOverrides(*overrides, draft.importPlaces[i].parent_pointer() / "lights", entry, static_cast<int>(i),
                                firstLight, scene);
        if (const Json* overrides = draft.importOverrides[i])
            applyMaterialOverrides(*overrides, draft.importPlaces[i].parent_pointer() / "materials", entry, first, scene,
                                   overrideTextures);
    }
    resolveTextures(overrideTextures, sceneFile, scope, scene);
}

} // namespace ptview::sceneFile
