#include <ptview/gpudata/QuadLightReach.h>

#include <ptview/geometry/Bvh.h>
#include <ptview/gpudata/SceneRecords.h>

#include <cmath>
#include <limits>
#include <vector>

namespace ptview {
namespace {

// The boxes around every surface: each sphere, quad and disk, and each mesh instance (an
// infinite box for a mesh without data, which reaches everything).
std::vector<Aabb> surfaceBounds(const Scene& scene, const ScenePrimitives& primitives) {
    std::vector<Aabb> bounds;
    for (const GpuQuad& quad : primitives.quads) bounds.push_back(primitiveBounds(quad));
    for (const GpuSphere& sphere : primitives.spheres) bounds.push_back(primitiveBounds(sphere));
    for (const GpuDisk& disk : primitives.disks) bounds.push_back(primitiveBounds(disk));
    const float infinity = std::numeric_limits<float>::infinity();
    for (const Shape& shape : scene.shapes) {
        if (shape.type != ShapeType::Mesh) continue;
        const TriangleMesh* mesh = shape.mesh >= 0 && shape.mesh < static_cast<int>(scene.meshes.size())
                                       ? scene.meshes[static_cast<std::size_t>(shape.mesh)].data.get()
                                       : nullptr;
        if (!mesh) {
            bounds.push_back(Aabb{glm::vec3(-infinity), glm::vec3(infinity)});
            continue;
        }
        Aabb object;
        for (glm::vec3 position : mesh->positions) object.extend(position);
        bounds.push_back(transformedBounds(object, shape.transform.objectToWorld()));
    }
    return bounds;
}

// Whether `box` meets the ball of squared radius reach2 around `center` and reaches past the
// plane through `center` with unit normal `front` by more than `planeTolerance`. So a surface
// that only touches the light's plane (the light itself, a box's other faces, a ceiling it is set
// into) is behind it, as sampleQuadLight sees points in the plane. A point that near the plane
// sees the quad edge-on or from right above it, at a solid angle sphericalRectangleUsable
// rejects, except within the tolerance of an edge; there area sampling is as correct, only noisier.
bool reachesFront(const Aabb& box, glm::vec3 center, glm::vec3 front, float reach2, float planeTolerance) {
    if (box.empty()) return false;
    glm::vec3 nearest = glm::clamp(center, box.min, box.max);
    glm::vec3 offset = nearest - center;
    if (!(glm::dot(offset, offset) <= reach2)) return false;
    // The corner farthest along `front`.
    glm::vec3 farthest(front.x > 0.0f ? box.max.x : box.min.x, front.y > 0.0f ? box.max.y : box.min.y,
                       front.z > 0.0f ? box.max.z : box.min.z);
    return !(glm::dot(farthest - center, front) <= planeTolerance);
}

} // namespace

bool surfaceWithinQuadLightReach(const Scene& scene) {
    ScenePrimitives primitives = flattenScene(scene);
    std::vector<Aabb> surfaces;
    bool surfacesKnown = false;
    for (std::size_t i = 0; i < primitives.quads.size(); ++i) {
        const Material& material = scene.materials[static_cast<std::size_t>(primitives.quadMaterials[i])];
        if (material.radiance == glm::vec3(0.0f)) continue; // as sceneFeatures: not a light
        const GpuQuad& quad = primitives.quads[i];
        glm::vec3 center(quad.center), u(quad.u), v(quad.v);
        glm::vec3 front = glm::normalize(glm::vec3(quad.normal));
        // 1e-3 more than lights.glsl's reach, for its float rounding.
        float reach2 = 1.001f * kSolidAngleSamplingMaxDistance * kSolidAngleSamplingMaxDistance *
                       (glm::dot(u, u) + glm::dot(v, v));
        if (!std::isfinite(reach2) || !std::isfinite(front.x + front.y + front.z)) return true;
        if (!surfacesKnown) {
            surfaces = surfaceBounds(scene, primitives);
            surfacesKnown = true;
        }
        float planeTolerance = 1e-5f * std::sqrt(reach2);
        for (const Aabb& box : surfaces)
            if (reachesFront(box, center, front, reach2, planeTolerance)) return true;
    }
    return false;
}

} // namespace ptview
