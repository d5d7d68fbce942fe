#pragma once
// A picture of the paths behind a pixel for a handout (`ptview paths --image`): the scene
// path-traced from a second camera, and the paths drawn over it as lines on the CPU, coloured by
// kind (docs/teaching.md has the legend). Lines are drawn over everything, not depth-tested: a
// path behind a wall still shows.

#include <ptview/io/Image.h>
#include <ptview/tracer/PathTracer.h>
#include <ptview/tracer/RecordedPath.h>
#include <ptview/scene/Scene.h>

#include <glm/glm.hpp>

#include <optional>
#include <utility>
#include <vector>

namespace ptview {

enum class PathSegment { Camera, Bsdf, ShadowReached, ShadowBlocked, Escaped };

// The colour each kind is drawn in (sRGB 8-bit).
glm::u8vec3 pathSegmentColor(PathSegment kind);
// The colour of a vertex's marker: white at a surface, green where a medium scattered the path;
// nullopt for the camera and an escape, which get none.
std::optional<glm::u8vec3> pathVertexColor(PathVertex::Kind kind);

// The second camera: `eye` when given (looking at the scene camera's target), else the scene
// camera turned sideways by kSideViewDegrees about its up axis through the target.
constexpr float kSideViewDegrees = 35.0f;
CameraDesc sideViewCamera(const CameraDesc& camera, std::optional<glm::vec3> eye);

// Where `camera` sees a world point on an image of `size`: pixels from the top-left corner; nullopt
// behind the camera.
std::optional<glm::vec2> projectToImage(const CameraDesc& camera, glm::ivec2 size, glm::vec3 point);
// A segment from `from` to `to` as `camera` sees it on an image of `size`, cut at a near plane
// (a side view's camera ray starts behind it); nullopt when all of it is behind.
std::optional<std::pair<glm::vec2, glm::vec2>> projectSegment(const CameraDesc& camera, glm::ivec2 size, glm::vec3 from,
                                                              glm::vec3 to);

// A path as the lines drawn for it: the camera ray, the BSDF samples, each vertex's shadow ray
// (up to the blocker when blocked) and an escape (escapeLength long, as a shadow ray to a light at
// infinity). `vertex`: the vertex the segment leaves from (a shadow ray's, or the one before).
struct PathLine {
    glm::vec3 from, to;
    PathSegment kind;
    int vertex;
};
std::vector<PathLine> pathLines(const RecordedPath& path, float escapeLength);

// Renders `spp` samples of the scene from `view` with the tracer's settings (the tracer's camera
// is left as `view`), tone-maps them with `display` and draws the paths. escapeLength: how far an
// escaped ray is drawn (world units).
ImageRgba8 drawPathsPicture(PathTracer& tracer, const CameraDesc& view, const std::vector<RecordedPath>& paths,
                            int spp, const DisplaySettings& display, float escapeLength);

} // namespace ptview
