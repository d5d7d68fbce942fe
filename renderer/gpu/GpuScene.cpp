#include <ptview/gpu/GpuScene.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cstring>
#include <cmath>
#include <limits>

namespace ptview {
const char* const GpuScene::kIntUniformNames[kIntUniformCount] = {
    GpuTextures::kRecordStartName, "uSphereCount", "uQuadCount", "uDiskCount", "uLightCount", "uEnvironmentLight",
    "uMeshInstanceCount", "uTopLevelRoot", "uMeshAttributeStart", "uMediaInScene", "uCameraMediumDepth"};

const char* const GpuScene::kSamplerNames[kTextureCount] = {
    "uSpheres", "uQuads", "uDisks", "uPrimitiveIds", "uMaterials", "uLights",
    GpuMeshes::kSamplerNames[0], GpuMeshes::kSamplerNames[1], GpuMeshes::kSamplerNames[2], GpuTextures::kSamplerName};

void GpuScene::upload(const Scene& scene, std::optional<glm::vec3> environmentMeanRadiance) {
    geometry_ = flattenScene(scene);
    textures_[0].fill(GL_RGBA32F, 16, geometry_.spheres);
    textures_[1].fill(GL_RGBA32F, 16, geometry_.quads);
    textures_[2].fill(GL_RGBA32F, 16, geometry_.disks);
    meshes_.upload(scene);
    atlas_.upload(scene.textures);
    sceneRadius_ = sceneBoundingRadius(geometry_, meshes_.worldBounds());
    environmentRadiance_ = environmentMeanRadiance.value_or(scene.environment);
    uploadMaterials(scene.materials);
}

void GpuScene::uploadMeshTangentsIfChanged(const Scene& scene) {
    if (meshes_.tangentsChanged(scene)) meshes_.upload(scene);
}

void GpuScene::uploadMaterials(const std::vector<Material>& materials) {
    ScenePrimitives primitives;
    flattenMaterials(materials, primitives);
    mediaInScene_ = std::any_of(materials.begin(), materials.end(), [](const Material& m) { return m.boundsMedium(); });
    // The texture records follow the materials in one buffer (textures.glsl), which saves a unit.
    std::vector<glm::vec4> texels(primitives.materials.size() * kMaterialTexels +
                                  atlas_.records().size() * kTextureRecordTexels);
    if (!primitives.materials.empty())
        std::memcpy(texels.data(), primitives.materials.data(), primitives.materials.size() * sizeof(GpuMaterial));
    textureRecordStart_ = static_cast<int>(primitives.materials.size() * kMaterialTexels);
    if (!atlas_.records().empty())
        std::memcpy(texels.data() + textureRecordStart_, atlas_.records().data(),
                    atlas_.records().size() * sizeof(GpuTextureRecord));
    textures_[4].fill(GL_RGBA32F, 16, texels);
    lights_ = buildLightTable(geometry_, materials, environmentRadiance_, meshes_.instances(), meshes_.worldBounds());
    // One id buffer: spheres, then quads, then disks (scene_data.glsl adds the offsets).
    std::vector<GpuPrimitiveIds> ids = lights_.sphereIds;
    ids.insert(ids.end(), lights_.quadIds.begin(), lights_.quadIds.end());
    ids.insert(ids.end(), lights_.diskIds.begin(), lights_.diskIds.end());
    textures_[3].fill(GL_RG32I, 8, ids);
    textures_[5].fill(GL_RGBA32F, 16, lights_.lights);
    meshes_.uploadInstances(lights_.meshInstanceLightBase);
}

void GpuScene::attach(const GlProgram& program, int firstUnit) {
    firstUnit_ = firstUnit;
    for (int i = 0; i < kTextureCount; ++i) program.bindSamplerUnit(kSamplerNames[i], firstUnit + i);
    for (int i = 0; i < kIntUniformCount; ++i) intUniformLocations_[i] = program.uniformLocation(kIntUniformNames[i]);
    cameraMediaLocation_ = program.uniformLocation("uCameraMedia");
}

void GpuScene::setMediaAroundCamera(const std::vector<int>& materials) {
    const int kept = std::min(static_cast<int>(materials.size()), kMaxMediumDepth);
    const int first = static_cast<int>(materials.size()) - kept;
    cameraMedia_ = glm::ivec4(0);
    for (int i = 0; i < kept; ++i) cameraMedia_[i] = materials[static_cast<std::size_t>(first + i)];
    cameraMediumDepth_ = kept;
}

void GpuScene::bind() const {
    for (int i = 0; i < kOwnTextureCount; ++i) textures_[i].bind(firstUnit_ + i);
    meshes_.bind(firstUnit_ + kOwnTextureCount);
    atlas_.bind(firstUnit_ + kOwnTextureCount + GpuMeshes::kTextureCount);
    const int values[kIntUniformCount] = {textureRecordStart_, sphereCount(), quadCount(), diskCount(), lightCount(),
                                          environmentLight(), meshes_.instanceCount(), meshes_.topLevelRoot(),
                                          meshes_.attributeStart(), mediaInScene_ ? 1 : 0, cameraMediumDepth_};
    for (int i = 0; i < kIntUniformCount; ++i) glUniform1i(intUniformLocations_[i], values[i]);
    glUniform4i(cameraMediaLocation_, cameraMedia_.x, cameraMedia_.y, cameraMedia_.z, cameraMedia_.w);
}

} // namespace ptview
