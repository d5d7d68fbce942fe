#pragma once
// The scene on the GPU: its records (gpudata/SceneRecords.h, LightTable.h) in the buffer
// textures that shaders/scene_data.glsl reads.

#include <ptview/gl/BufferTexture.h>
#include <ptview/gpudata/GpuLayout.h>
#include <ptview/gl/GlProgram.h>
#include <ptview/gpu/GpuMeshes.h>
#include <ptview/gpudata/SurfaceHit.h>
#include <ptview/gpu/GpuTextures.h>
#include <ptview/gpudata/LightTable.h>
#include <ptview/gpudata/SceneRecords.h>
#include <ptview/gpudata/LightKind.h>
#include <ptview/scene/Scene.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace ptview {

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
    // The media the camera is in (mediaAroundPoint of its eye, outermost first): where every
    // camera ray starts (shaders/media.glsl). Only the innermost kMaxMediumDepth are kept.
    void setMediaAroundCamera(const std::vector<int>& materials);
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
    float sceneRadius_ = 1.0f;
    int firstUnit_ = 0;
    // The int uniforms bind() sets, in the order of the values it sets them to: the texture
    // records' start, the shape and light counts, the environment's light, the meshes' top level,
    // whether a material bounds a medium and how many media the camera is in.
    static constexpr int kIntUniformCount = 11;
    static const char* const kIntUniformNames[kIntUniformCount];
    GLint intUniformLocations_[kIntUniformCount] = {-1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1};
    // shaders/media.glsl's kMaxMediumDepth: the media a ray can be in at once.
    static constexpr int kMaxMediumDepth = 4;
    GLint cameraMediaLocation_ = -1;
    bool mediaInScene_ = false;
    glm::ivec4 cameraMedia_{0};
    int cameraMediumDepth_ = 0;
    ScenePrimitives geometry_; // kept to rebuild the light table on material edits
    glm::vec3 environmentRadiance_{0.0f};
    LightTable lights_;
};

} // namespace ptview
