#include <ptview/scene/MediaAroundPoint.h>

#include <ptview/scene/MediumBoundaries.h>

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace ptview {
namespace {

// Whether the ray from `origin` along `direction` crosses the triangle (Moller-Trumbore).
bool crosses(glm::vec3 origin, glm::vec3 direction, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const glm::vec3 e1 = b - a, e2 = c - a;
    const glm::vec3 p = glm::cross(direction, e2);
    const float det = glm::dot(e1, p);
    if (det == 0.0f) return false;
    const glm::vec3 s = origin - a;
    const float u = glm::dot(s, p) / det;
    if (u < 0.0f || u > 1.0f) return false;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(direction, q) / det;
    if (v < 0.0f || u + v > 1.0f) return false;
    return glm::dot(e2, q) / det > 0.0f;
}

// Inside a mesh's medium-bounding triangles (object space), by the parity of a ray's crossings.
// The direction is skewed off the axes so that it does not run along the edges of axis-aligned
// models. Returns the enclosed volume's measure for ordering (the bounds' volume), or -1 outside.
float meshVolumeAround(const Scene& scene, const Shape& shape, glm::vec3 pointObject) {
    const TriangleMesh& mesh = *scene.meshes[static_cast<std::size_t>(shape.mesh)].data;
    const glm::vec3 direction = glm::normalize(glm::vec3(0.5773f, 0.6125f, 0.5398f));
    int crossings = 0;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const MeshTriangle& triangle : mesh.triangles) {
        const std::size_t slot = static_cast<std::size_t>(triangle.materialSlot);
        if (slot >= shape.slotMaterials.size() || !boundsMedium(scene, shape.slotMaterials[slot])) continue;
        const glm::vec3& a = mesh.positions[triangle.position[0]];
        const glm::vec3& b = mesh.positions[triangle.position[1]];
        const glm::vec3& c = mesh.positions[triangle.position[2]];
        for (const glm::vec3& corner : {a, b, c}) lo = glm::min(lo, corner), hi = glm::max(hi, corner);
        if (crosses(pointObject, direction, a, b, c)) ++crossings;
    }
    if (crossings % 2 == 0) return -1.0f;
    const glm::vec3 extent = hi - lo;
    return extent.x * extent.y * extent.z * std::abs(glm::determinant(glm::mat3(shape.transform.objectToWorld())));
}

} // namespace

std::vector<int> mediaAroundPoint(const Scene& scene, glm::vec3 point) {
    std::vector<std::pair<float, int>> around; // (volume, material)
    for (const Shape& shape : scene.shapes) {
        switch (shape.type) {
        case ShapeType::Sphere:
            if (boundsMedium(scene, shape.material) && glm::length(point - shape.center) < shape.radius)
                around.emplace_back(shape.radius * shape.radius * shape.radius * 4.18879f, shape.material);
            break;
        case ShapeType::Box: {
            if (!boundsMedium(scene, shape.material)) break;
            const glm::vec3 local = glm::transpose(rotationMatrix(shape.rotationAxis, shape.rotationDeg)) * (point - shape.center);
            if (glm::all(glm::lessThan(glm::abs(local), shape.halfSize)))
                around.emplace_back(8.0f * shape.halfSize.x * shape.halfSize.y * shape.halfSize.z, shape.material);
            break;
        }
        case ShapeType::Mesh: {
            if (shape.mesh < 0 || !scene.meshes[static_cast<std::size_t>(shape.mesh)].data) break;
            const glm::vec3 pointObject = glm::vec3(glm::inverse(shape.transform.objectToWorld()) * glm::vec4(point, 1.0f));
            // A mesh with media on several slots counts as one volume, of the first such slot's material.
            int material = -1;
            for (int m : shape.slotMaterials)
                if (boundsMedium(scene, m)) { material = m; break; }
            if (material < 0) break;
            const float volume = meshVolumeAround(scene, shape, pointObject);
            if (volume >= 0.0f) around.emplace_back(volume, material);
            break;
        }
        case ShapeType::Quad:
        case ShapeType::Disk: break; // encloses nothing (the loaders refuse a medium on one)
        }
    }
    std::stable_sort(around.begin(), around.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<int> materials;
    for (const auto& [volume, material] : around) materials.push_back(material);
    return materials;
}

} // namespace ptview
