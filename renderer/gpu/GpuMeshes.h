#pragma once
// The scene's triangle meshes on the GPU, as a two-level BVH: one tree per mesh over its
// triangles in object space (the bottom level, shared by all instances of the mesh) and one over
// the mesh shapes' world bounds (the top level). Three buffer textures hold it all;
// shaders/mesh_intersect.glsl traverses them.

#include <ptview/gl/BufferTexture.h>
#include <ptview/geometry/Bvh.h>
#include <ptview/gpudata/GpuLayout.h>
#include <ptview/gpudata/SceneRecords.h>
#include <ptview/scene/Scene.h>

#include <cstdint>
#include <map>
#include <memory>
#include <vector>

namespace ptview {

class GpuMeshes {
public:
    static constexpr int kTextureCount = 3;
    // The sampler uniforms of shaders/mesh_intersect.glsl, in the order bind() uses units.
    static const char* const kSamplerNames[kTextureCount];

    // Builds (or reuses, for mesh data seen before) each mesh's BVH, the top-level BVH over the
    // mesh shapes, and uploads nodes and triangles. Instances follow with uploadInstances, once
    // the light table has given each its first light.
    void upload(const Scene& scene);
    // lightBase[i]: the light index of instances()[i]'s first triangle, or -1 when it emits none.
    void uploadInstances(const std::vector<std::int32_t>& lightBase);
    void bind(int firstUnit) const;

    int instanceCount() const { return static_cast<int>(instances_.size()); }
    int topLevelRoot() const { return topLevelRoot_; } // -1: no meshes
    // The texel of the triangles' buffer where their attributes begin (GpuTriangle).
    int attributeStart() const { return attributeStart_; }
    std::size_t triangleCount() const { return triangleCount_; }
    const std::vector<MeshInstance>& instances() const { return instances_; }
    Aabb worldBounds() const { return worldBounds_; }

    // Whether upload(scene) would store tangents for other meshes than the last upload did (a
    // material edit that adds or removes a normal map): then the meshes need uploading again.
    bool tangentsChanged(const Scene& scene) const;

    // What the last upload cost, for `ptview bench`: all of it, and of that the tangents.
    double lastBuildSeconds() const { return lastBuildSeconds_; }
    double lastTangentSeconds() const { return lastTangentSeconds_; }
    std::size_t gpuBytes() const { return gpuBytes_; }

private:
    struct BuiltMesh {
        std::vector<GpuBvhNode> nodes;      // packed once, references relative to this mesh
        std::vector<GpuTriangle> triangles; // leaf order
        std::vector<glm::vec4> tangents;    // three per triangle, leaf order; empty without
        Aabb bounds;                        // object space
    };
    // withTangents: the corners' tangents too (BuiltMesh::tangents; the triangles' tangentTexel
    // then counts from the mesh's first tangent texel).
    static BuiltMesh buildMesh(const TriangleMesh& mesh, bool withTangents, double& tangentSeconds);
    using MeshKey = std::pair<const TriangleMesh*, bool>; // the data, and whether with tangents

    BufferTexture textures_[kTextureCount];
    // Keyed by the mesh data: a reload that reads the same file again builds again, but instances
    // of one mesh and uploads of an unchanged scene do not.
    std::map<MeshKey, std::shared_ptr<BuiltMesh>> built_;
    std::vector<std::shared_ptr<const TriangleMesh>> keepAlive_; // so the keys above stay valid
    std::vector<MeshInstance> instances_;        // in top-level leaf order
    std::vector<std::uint32_t> instanceRoots_;   // bottom-level root node of each instance
    int topLevelRoot_ = -1;
    int attributeStart_ = 0;
    std::size_t triangleCount_ = 0;
    Aabb worldBounds_;
    double lastBuildSeconds_ = 0.0;
    double lastTangentSeconds_ = 0.0;
    std::vector<const TriangleMesh*> withTangents_; // the meshes the last upload stored tangents for
    std::size_t gpuBytes_ = 0;
};

} // namespace ptview
