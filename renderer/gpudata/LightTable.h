#pragma once
// The light table, built without OpenGL: every emitting primitive, triangle, point and spot light
// and the environment, with the cumulative probabilities light sampling searches
// (shaders/lights.glsl).

#include <ptview/gpudata/GpuLayout.h>
#include <ptview/gpudata/LightKind.h>
#include <ptview/gpudata/SceneRecords.h>

#include <cstdint>
#include <vector>

namespace ptview {

// Every light the integrators can sample, chosen in proportion to its emitted power.
struct LightTable {
    std::vector<GpuLight> lights; // each with its cumulative selection probability; the last's is 1
    std::vector<GpuPrimitiveIds> sphereIds, quadIds, diskIds;
    std::vector<std::int32_t> meshInstanceLightBase; // per mesh instance: its first light, or -1
    std::int32_t environmentLight = -1;
};

// The environment's share is its power through a disk as large as the scene's bounding sphere.
// An emitting mesh instance gets one light per triangle (in its leaf order), so that a hit's light
// index is the instance's first plus the triangle's place.
LightTable buildLightTable(const ScenePrimitives& geometry, const std::vector<Material>& materials,
                           glm::vec3 environmentRadiance, const std::vector<MeshInstance>& meshInstances = {},
                           const Aabb& meshBounds = {});

} // namespace ptview
