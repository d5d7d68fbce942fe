#pragma once
// The media a point is in: where a camera ray starts (shaders/media.glsl takes them as the
// stack every camera ray begins with), so that fog around the camera needs nothing in the file.

#include <ptview/scene/Scene.h>

#include <vector>

namespace ptview {

// The materials of the shapes bounding a medium (Material::boundsMedium) that contain `point`,
// outermost first: a medium inside another has the smaller volume. Meshes by the parity of a
// ray's crossings of their medium-bounding triangles. A point on a boundary counts as outside.
std::vector<int> mediaAroundPoint(const Scene& scene, glm::vec3 point);

} // namespace ptview
