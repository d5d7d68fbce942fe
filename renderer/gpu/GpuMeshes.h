#pragma once
// The scene's triangle meshes on the GPU, as a two-level BVH: one tree per mesh over its
// triangles in object space (the bottom level, shared by all instances of the mesh) and one over
// the mesh shapes' world bounds (the top level). Three buffer textures hold it all;
// shaders/mesh_intersect.glsl traverses them.

#include "BufferTexture.h"
#include "Bvh.h"
#include "Scene.h"

#include <cstdint>
#include <map>
#include <memory>
#include <vector>

namespace ptview {

// shaders/mesh_intersect.glsl: a BVH node as two RGBA32F texels, with its integers as float values
// (GpuLayout.h says why).
struct GpuBvhNode {
    glm::vec3 boundsMin;
    float firstOrRight; // leaf: first triangle (or instance); interior: right child
    glm::vec3 boundsMax;
    float count;        // primitives in a leaf; 0 for an interior node
};
static_assert(sizeof(GpuBvhNode) == 32, "two RGBA32F texels");

// shaders/mesh_intersect.glsl: seven RGBA32F texels per triangle, in the order of its mesh's BVH
// leaves (so a leaf's triangles are contiguous). Triangles of meshes that a normal-mapped material
// covers have three more texels, after all triangles in the same buffer: the corners' tangents
// (xyz unit, w the bitangent's sign: MeshTangents.h); other meshes carry none.
struct GpuTriangle {
    glm::vec3 p0;
    float materialSlot; // into the instance's material table (an integer value: GpuLayout.h)
    glm::vec3 p1;
    float tangentTexel; // first of the triangle's three tangent texels in the buffer; -1: none
    glm::vec3 p2;
    float pad1;
    glm::vec4 n0AndU0;  // per-corner shading normals (0: none, use the geometric normal) and
    glm::vec4 n1AndV0;  // texture coordinates (0 when the mesh has none)
    glm::vec4 n2AndU1;
    glm::vec4 v1U2V2;   // (v1, u2, v2, -)
};
static_assert(sizeof(GpuTriangle) == 112, "seven RGBA32F texels");
constexpr int kTriangleTexels = sizeof(GpuTriangle) / 16; // generated into gpu_layout.glsl

// Texels per instance: world-to-object and object-to-world rows (three each), (bottom-level root,
// first triangle, material table offset, first light or -1), and a spare texel (uploadInstances).
constexpr int kInstanceTexels = 8;

// An instance as the light table sees it: its triangles in world space come from these.
struct MeshInstance {
    int shape;                 // index in Scene::shapes
    glm::mat4 objectToWorld;
    const std::vector<GpuTriangle>* triangles; // in leaf order, object space
    std::uint32_t triangleOffset;              // of triangles[0] in the GPU's triangle buffer
    std::vector<int> slotMaterials;            // scene material per material slot
};

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
        Bvh bvh;
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
    std::size_t triangleCount_ = 0;
    Aabb worldBounds_;
    double lastBuildSeconds_ = 0.0;
    double lastTangentSeconds_ = 0.0;
    std::vector<const TriangleMesh*> withTangents_; // the meshes the last upload stored tangents for
    std::size_t gpuBytes_ = 0;
};

} // namespace ptview
