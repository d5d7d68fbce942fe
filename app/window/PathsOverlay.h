#pragma once
// The paths behind the pinned pixel drawn over the image in the window (ViewerSession::tracePaths):
// ImGui draw-list lines projected on the CPU with the view's camera as it is now, so orbiting
// shows them in 3D from the side while the path-traced image re-renders from the new view. The
// same lines and colours as `ptview paths --image` (PathsPicture.h).

#include <ptview/session/ViewerSession.h>

#include <glm/glm.hpp>

#include <optional>

struct ImDrawList;

namespace ptview {

// Where the render is on screen, in ImGui's window coordinates (top-left origin).
struct ScreenRect {
    glm::vec2 topLeft{0.0f};
    glm::vec2 size{0.0f};
};

// A path and one of its vertices (-1: none).
struct PathPick {
    int path = -1;
    int vertex = -1;
};

// `camera` and `renderSize`: the view's now. The selected path is drawn on top and wider, the
// selected vertex ringed.
void drawPathsOverlay(ImDrawList& draw, const ViewerSession::TracedPaths& traced, const CameraDesc& camera,
                      glm::ivec2 renderSize, ScreenRect image, PathPick selected, float escapeLength);

// The vertex (camera excluded) nearest `point` within kPickRadius window units, if any.
constexpr float kPickRadius = 8.0f;
std::optional<PathPick> pickPathVertex(const ViewerSession::TracedPaths& traced, const CameraDesc& camera,
                                       glm::ivec2 renderSize, ScreenRect image, glm::vec2 point);

} // namespace ptview
