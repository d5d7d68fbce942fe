#pragma once
// Where a medium's boundary is open. A ray's medium changes as it crosses the surface of a shape
// that bounds one (Material::boundsMedium), so that surface must enclose a volume: through a quad,
// a disk or a mesh with a hole a ray could enter a medium and never leave it, and every ray from
// there on would be in the wrong medium. The loaders refuse such a scene (docs/volumes.md).

#include <ptview/scene/Scene.h>

#include <cstddef>
#include <optional>
#include <string>

namespace ptview {

// Whether scene.materials[material] bounds a medium; false for an index out of range (a shape's
// material not yet resolved).
bool boundsMedium(const Scene& scene, int material);

struct OpenMediumBoundary {
    std::size_t shape; // into Scene::shapes
    std::string what;  // "a quad encloses no volume", "the edge from (x, y, z) to (x, y, z) ..."
};

// The first shape, in the scene's order, whose surface bounds a medium but is not closed: a quad
// or a disk, or a mesh whose triangles of such materials leave an edge with one triangle on it
// (corners compared by position, so a seam of split vertices is no hole). nullopt: none.
std::optional<OpenMediumBoundary> findOpenMediumBoundary(const Scene& scene);

} // namespace ptview
