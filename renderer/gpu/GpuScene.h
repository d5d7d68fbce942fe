#pragma once
// The scene as GPU primitives: boxes become six quads, emitters and point/spot lights become a
// light table, and everything goes into buffer textures that shaders/scene_data.glsl reads.

#include "BufferTexture.h"
#include "EnumTable.h"
#include "GpuLayout.h"
#include "GlProgram.h"
#include "GpuMeshes.h"
#include "SurfaceHit.h"
#include "GpuTextures.h"
#include "LightKind.h"
#include "Scene.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace ptview {

struct ScenePrimitives {
    std::vector<GpuSphere> spheres;
    std::vector<std::int32_t> sphereMaterials;
    std::vector<GpuQuad> quads;
    std::vector<std::int32_t> quadMaterials;
    std::vector<GpuDisk> disks;
    std::vector<std::int32_t> diskMaterials;
    std::vector<Light> lights; // point and spot
    std::vector<GpuMaterial> materials;
};

// Every light the integrators can sample, chosen in proportion to its emitted power.
struct LightTable {
    std::vector<GpuLight> lights; // each with its cumulative selection probability; the last's is 1
    std::vector<GpuPrimitiveIds> sphereIds, quadIds, diskIds;
    std::vector<std::int32_t> meshInstanceLightBase; // per mesh instance: its first light, or -1
    std::int32_t environmentLight = -1;
};

// Pure CPU steps, testable without a GL context.
// The box around a primitive (around a disk, the box of its sphere).
Aabb primitiveBounds(const GpuQuad& quad);
Aabb primitiveBounds(const GpuSphere& sphere);
Aabb primitiveBounds(const GpuDisk& disk);
// Half the diagonal of the box around every primitive (1 for an empty scene).
float sceneBoundingRadius(const ScenePrimitives& geometry, const Aabb& meshBounds = {});
ScenePrimitives flattenScene(const Scene& scene);
// The scene shape whose primitive the GPU intersected: index counts flattenScene's primitives of
// that kind (a box gives six quads), or, for a mesh instance, meshInstances in GpuMeshes' order.
// -1 when there is no such primitive.
int shapeOfPrimitive(const Scene& scene, PrimitiveKind kind, int index, const std::vector<MeshInstance>& meshInstances);
void flattenMaterials(const std::vector<Material>& materials, ScenePrimitives& out);
// The environment's share is its power through a disk as large as the scene's bounding sphere.
// An emitting mesh instance gets one light per triangle (in its leaf order), so that a hit's light
// index is the instance's first plus the triangle's place.
LightTable buildLightTable(const ScenePrimitives& geometry, const std::vector<Material>& materials,
                           glm::vec3 environmentRadiance, const std::vector<MeshInstance>& meshInstances = {},
                           const Aabb& meshBounds = {});

class GpuScene {
public:
    static constexpr int kOwnTextureCount = 6;
    static constexpr int kTextureCount = kOwnTextureCount + GpuMeshes::kTextureCount + 1; // + the texture atlas
    // The sampler uniforms of shaders/scene_data.glsl, in the order bind() uses units.
    static const char* const kSamplerNames[kTextureCount];

    // Points program's samplers at units firstUnit .. firstUnit + kTextureCount - 1 and finds its
    // scene uniforms (counts, the environment's light, the meshes' top-level root); again
    // whenever the program is rebuilt.
    void attach(const GlProgram& program, int firstUnit);

    // environmentMeanRadiance: the environment's radiance averaged over all directions, which sets
    // its share of light samples; by default scene.environment (an environment map's mean instead).
    void upload(const Scene& scene, std::optional<glm::vec3> environmentMeanRadiance = std::nullopt);
    // Material edits only: no geometry is re-sent and nothing is recompiled. The light table is
    // rebuilt, since an edit can make a surface an emitter or change its power.
    void uploadMaterials(const std::vector<Material>& materials);
    // Before uploadMaterials, for an edit that adds or removes a normal map on a mesh: re-sends
    // the meshes when the set of those that need tangents changed (scene: with the new materials).
    void uploadMeshTangentsIfChanged(const Scene& scene);
    // Binds the textures and sets the uniforms of the attached program, which must be in use.
    void bind() const;

    int sphereCount() const { return static_cast<int>(geometry_.spheres.size()); }
    int quadCount() const { return static_cast<int>(geometry_.quads.size()); }
    int diskCount() const { return static_cast<int>(geometry_.disks.size()); }
    int lightCount() const { return static_cast<int>(lights_.lights.size()); }
    int environmentLight() const { return lights_.environmentLight; }
    const GpuMeshes& meshes() const { return meshes_; }
    const GpuTextures& textures() const { return atlas_; }
    float sceneRadius() const { return sceneRadius_; }

private:
    BufferTexture textures_[kOwnTextureCount];
    GpuMeshes meshes_;
    GpuTextures atlas_;
    int textureRecordStart_ = 0;
    GLint textureRecordStartLocation_ = -1;
    float sceneRadius_ = 1.0f;
    int firstUnit_ = 0;
    GLint sphereCountLocation_ = -1;
    GLint quadCountLocation_ = -1;
    GLint diskCountLocation_ = -1;
    GLint lightCountLocation_ = -1;
    GLint environmentLightLocation_ = -1;
    GLint meshInstanceCountLocation_ = -1;
    GLint topLevelRootLocation_ = -1;
    ScenePrimitives geometry_; // kept to rebuild the light table on material edits
    glm::vec3 environmentRadiance_{0.0f};
    LightTable lights_;
};

} // namespace ptview
