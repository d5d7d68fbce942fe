#include <ptview/scene/MediumBoundaries.h>

#include <ptview/scene/MaterialSchema.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <map>
#include <utility>
#include <vector>

namespace ptview {
namespace {

std::string pointText(const glm::vec3& p) {
    char text[96];
    std::snprintf(text, sizeof text, "(%g, %g, %g)", p.x, p.y, p.z);
    return text;
}

// The first edge of the mesh's medium-bounding triangles that an odd number of them share (a
// closed surface has every edge on two, or on an even number where surfaces touch); nullopt: closed.
std::optional<std::string> openEdge(const Scene& scene, const Shape& shape) {
    const TriangleMesh& mesh = *scene.meshes[static_cast<std::size_t>(shape.mesh)].data;
    // One index per distinct position: a glTF file splits a vertex where its normals or uvs differ.
    std::map<std::array<float, 3>, std::uint32_t> welded;
    std::vector<std::uint32_t> weldedIndex(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3& p = mesh.positions[i];
        weldedIndex[i] = welded.emplace(std::array<float, 3>{p.x, p.y, p.z}, static_cast<std::uint32_t>(welded.size())).first->second;
    }
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<int, std::size_t>> edges; // uses, first triangle
    bool any = false;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const MeshTriangle& triangle = mesh.triangles[t];
        const std::size_t slot = static_cast<std::size_t>(triangle.materialSlot);
        if (slot >= shape.slotMaterials.size() || !boundsMedium(scene, shape.slotMaterials[slot])) continue;
        any = true;
        for (int corner = 0; corner < 3; ++corner) {
            std::uint32_t a = weldedIndex[triangle.position[static_cast<std::size_t>(corner)]];
            std::uint32_t b = weldedIndex[triangle.position[static_cast<std::size_t>((corner + 1) % 3)]];
            if (a == b) continue; // a degenerate triangle's collapsed edge
            auto [entry, added] = edges.emplace(std::minmax(a, b), std::make_pair(0, t));
            ++entry->second.first;
        }
    }
    if (!any) return std::nullopt;
    // The open edge met first in the file's triangle order, so the message is the same every run.
    std::optional<std::pair<std::size_t, std::pair<std::uint32_t, std::uint32_t>>> first;
    for (const auto& [edge, usesAndTriangle] : edges)
        if (usesAndTriangle.first % 2 == 1 && (!first || usesAndTriangle.second < first->first))
            first = std::make_pair(usesAndTriangle.second, edge);
    if (!first) return std::nullopt;
    std::vector<glm::vec3> byWelded(welded.size());
    for (const auto& [p, index] : welded) byWelded[index] = glm::vec3(p[0], p[1], p[2]);
    return "mesh '" + scene.meshes[static_cast<std::size_t>(shape.mesh)].name + "' is not closed: the edge from " +
           pointText(byWelded[first->second.first]) + " to " + pointText(byWelded[first->second.second]) +
           " (the mesh's own coordinates) of its triangle " + std::to_string(first->first) +
           " has no second triangle on it";
}

} // namespace

bool boundsMedium(const Scene& scene, int material) {
    return material >= 0 && static_cast<std::size_t>(material) < scene.materials.size() &&
           scene.materials[static_cast<std::size_t>(material)].boundsMedium();
}

std::optional<OpenMediumBoundary> findOpenMediumBoundary(const Scene& scene) {
    for (std::size_t i = 0; i < scene.shapes.size(); ++i) {
        const Shape& shape = scene.shapes[i];
        switch (shape.type) {
        case ShapeType::Sphere:
        case ShapeType::Box: break; // closed
        case ShapeType::Quad:
        case ShapeType::Disk:
            if (boundsMedium(scene, shape.material))
                return OpenMediumBoundary{i, std::string("a ") + (shape.type == ShapeType::Quad ? "quad" : "disk") +
                                                 " encloses no volume, so it cannot bound the medium of material '" +
                                                 scene.materials[static_cast<std::size_t>(shape.material)].name + "'"};
            break;
        case ShapeType::Mesh:
            if (shape.mesh < 0 || static_cast<std::size_t>(shape.mesh) >= scene.meshes.size() ||
                !scene.meshes[static_cast<std::size_t>(shape.mesh)].data)
                break;
            if (std::optional<std::string> open = openEdge(scene, shape))
                return OpenMediumBoundary{i, *open + ", so it cannot bound a medium"};
            break;
        }
    }
    return std::nullopt;
}

} // namespace ptview
