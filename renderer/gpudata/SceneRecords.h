#pragma once
// The scene as the GPU's records, built without OpenGL: boxes become six quads, materials their
// GpuMaterial, mesh instances what the light table reads (gpu/GpuScene.h uploads them all).

#include <ptview/gpudata/GpuLayout.h>
#include <ptview/gpudata/SurfaceHit.h>
#include <ptview/geometry/Bvh.h>
#include <ptview/scene/Scene.h>

#include <glm/glm.hpp>

#include <cstdint>
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

// An instance as the light table sees it: its triangles in world space come from these.
struct MeshInstance {
    int shape;                 // index in Scene::shapes
    glm::mat4 objectToWorld;
    const std::vector<GpuTriangle>* triangles; // in leaf order, object space
    std::uint32_t triangleOffset;              // of triangles[0] in the GPU's triangle buffer
    std::vector<int> slotMaterials;            // scene material per material slot
};

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

} // namespace ptview
