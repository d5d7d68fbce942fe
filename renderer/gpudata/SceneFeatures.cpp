#include <ptview/gpudata/SceneFeatures.h>

#include <ptview/gpudata/QuadLightReach.h>
#include <ptview/gpudata/SceneRecords.h>
#include <ptview/scene/MaterialSchema.h>
#include <ptview/scene/MaterialTextures.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <iterator>
#include <tuple>

namespace ptview {
namespace {

auto tied(const ShaderFeatures& f) {
    ShapeCounts unrolled = f.unrolledShapes.value_or(ShapeCounts{-1, -1, -1});
    return std::make_tuple(f.materialModels, f.lightKinds, f.quadLightsUpClose, f.environmentMap,
                           f.meshes, f.oneMeshInstance, f.textures, f.textureSlots, f.metallicFromRoughnessTexel, f.thinLens, f.normalMaps, f.alpha, f.media, unrolled.spheres, unrolled.quads,
                           unrolled.disks);
}

} // namespace

bool ShapeCounts::operator==(const ShapeCounts& other) const {
    return spheres == other.spheres && quads == other.quads && disks == other.disks;
}

ShapeCounts shapeCounts(const Scene& scene) {
    ScenePrimitives primitives = flattenScene(scene); // the primitives the GPU holds: a box is six quads
    return ShapeCounts{static_cast<int>(primitives.spheres.size()), static_cast<int>(primitives.quads.size()),
                       static_cast<int>(primitives.disks.size())};
}

ShaderFeatures ShaderFeatures::all() {
    ShaderFeatures features;
    for (const MaterialSchema& schema : kMaterialSchemas) features.materialModels |= 1u << static_cast<int>(schema.type);
    for (const auto& entry : lightKindNames()) features.lightKinds |= 1u << static_cast<int>(entry.value);
    features.quadLightsUpClose = features.environmentMap = features.meshes = features.textures = features.thinLens = true;
    features.normalMaps = features.alpha = features.media = true;
    features.textureSlots = (1u << std::size(kMaterialTextureInputs)) - 1u;
    return features;
}

bool ShaderFeatures::transmission() const {
    return usesModel(MaterialType::DiffuseTransmission) || usesModel(MaterialType::SpecularTransmission) ||
           usesModel(MaterialType::Glass) || usesModel(MaterialType::Principled);
}

bool ShaderFeatures::covers(const ShaderFeatures& other) const {
    return (other.materialModels & ~materialModels) == 0 && (other.lightKinds & ~lightKinds) == 0 &&
           (quadLightsUpClose || !other.quadLightsUpClose) &&
           (environmentMap || !other.environmentMap) && (meshes || !other.meshes) &&
           (!oneMeshInstance || other.oneMeshInstance || !other.meshes) &&
           (textures || !other.textures) && (other.textureSlots & ~textureSlots) == 0 &&
           (!metallicFromRoughnessTexel || other.metallicFromRoughnessTexel) && (thinLens || !other.thinLens) &&
           (normalMaps || !other.normalMaps) && (alpha || !other.alpha) && (media || !other.media) &&
           (!unrolledShapes || (other.unrolledShapes && *unrolledShapes == *other.unrolledShapes));
}

bool ShaderFeatures::operator==(const ShaderFeatures& other) const { return tied(*this) == tied(other); }
bool ShaderFeatures::operator<(const ShaderFeatures& other) const { return tied(*this) < tied(other); }

std::string ShaderFeatures::describe() const {
    std::string materials;
    for (const MaterialSchema& schema : kMaterialSchemas)
        if (usesModel(schema.type)) materials += std::string(" ") + schema.name;
    std::string textureInputs;
    for (std::size_t k = 0; k < std::size(kMaterialTextureInputs); ++k)
        if ((textureSlots >> k) & 1u) textureInputs += std::string(" ") + kMaterialTextureInputs[k].name;
    std::string lights;
    for (const auto& entry : lightKindNames())
        if (hasLightKind(entry.value)) lights += std::string(" ") + entry.name;
    return "materials:" + (materials.empty() ? std::string(" none") : materials) + "\n" +
           "lights:" + (lights.empty() ? std::string(" none") : lights) + "\n" +
           (hasLightKind(LightKind::Quad)
                ? std::string("quad lights sampled: ") + (quadLightsUpClose ? "by solid angle up close" : "by area") + "\n"
                : std::string()) +
           "environment: " + (environmentMap ? "map" : "constant") + "\n" +
           "meshes: " + (meshes ? (oneMeshInstance ? "one instance (BVH)" : "yes (two-level BVH)") : "no") + "\n" +
           "transmission: " + (transmission() ? "yes" : "no") + "\n" + "textures: " + (textures ? "yes" : "no") + textureInputs + "\n" +
           "camera: " + (thinLens ? "thin lens" : "pinhole") + "\n" +
           "normal maps: " + (normalMaps ? "yes" : "no") + "\n" +
           "alpha: " + (alpha ? "mask/blend" : "opaque") + "\n" +
           "media: " + (media ? "yes" : "no") + "\n" +
           "shape loops: " +
           (unrolledShapes ? "unrolled for " + std::to_string(unrolledShapes->spheres) + " spheres, " +
                                 std::to_string(unrolledShapes->quads) + " quads, " +
                                 std::to_string(unrolledShapes->disks) + " disks"
                           : std::string("over the counts set at run time")) +
           "\n";
}

ShaderFeatures sceneFeatures(const Scene& scene) {
    ShaderFeatures features;
    auto addLightKind = [&](LightKind kind) { features.lightKinds |= 1u << static_cast<int>(kind); };
    // An emitting surface is a light of its shape's kind (a superset of buildLightTable's test,
    // which also leaves out textured emission).
    bool metallicTextured = false, metallicApart = false; // apart: not from the roughness texel
    auto useMaterial = [&](int index, LightKind kind) {
        const Material& material = scene.materials[static_cast<std::size_t>(index)];
        features.materialModels |= 1u << static_cast<int>(material.type);
        if (material.radiance != glm::vec3(0.0f)) addLightKind(kind);
        if (material.hasTextures()) features.textures = true;
        for (std::size_t k = 0; k < std::size(kMaterialTextureInputs); ++k)
            if ((material.*kMaterialTextureInputs[k].slot).used()) features.textureSlots |= 1u << k;
        const TextureSlot& metallic = material.metallicTexture;
        const TextureSlot& roughness = material.roughnessTexture;
        metallicTextured = metallicTextured || metallic.used();
        if (metallic.used() && !(metallic.texture == roughness.texture && metallic.scale == roughness.scale &&
                                 metallic.offset == roughness.offset))
            metallicApart = true;
        if (material.normalTexture.used()) features.normalMaps = true;
        if (material.alphaMode != AlphaMode::Opaque) features.alpha = features.textures = true;
        if (material.boundsMedium()) features.media = true;
    };
    int meshShapes = 0;
    for (const Shape& shape : scene.shapes) {
        switch (shape.type) {
        case ShapeType::Mesh:
            features.meshes = true;
            ++meshShapes;
            for (int material : shape.slotMaterials) useMaterial(material, LightKind::Triangle);
            break;
        case ShapeType::Sphere: useMaterial(shape.material, LightKind::Sphere); break;
        case ShapeType::Quad:
        case ShapeType::Box: useMaterial(shape.material, LightKind::Quad); break;
        case ShapeType::Disk: useMaterial(shape.material, LightKind::Disk); break;
        }
    }
    for (const Light& light : scene.lights)
        addLightKind(light.type == LightType::Point ? LightKind::Point
                     : light.type == LightType::Spot ? LightKind::Spot
                                                     : LightKind::Directional);
    features.oneMeshInstance = meshShapes == 1;
    features.metallicFromRoughnessTexel = metallicTextured && !metallicApart;
    features.environmentMap = !scene.environmentMap.empty();
    if (features.environmentMap || scene.environment != glm::vec3(0.0f)) addLightKind(LightKind::Environment);
    features.thinLens = scene.camera.apertureRadius > 0.0f;
    // A point in a medium may come as close to a quad light as any surface.
    features.quadLightsUpClose = features.hasLightKind(LightKind::Quad) && (features.media || surfaceWithinQuadLightReach(scene));
    ShapeCounts counts = shapeCounts(scene);
    if (counts.total() <= ShaderFeatures::kMaxUnrolledShapes) features.unrolledShapes = counts;
    return features;
}

} // namespace ptview
