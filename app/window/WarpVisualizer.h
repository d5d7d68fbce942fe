#pragma once
// The viewer's warp visualizer: N points of a warp fed by a sampler, drawn in 3D and orbited with
// the mouse, with warp, sampler, N and the cone angle in an ImGui panel. Needs a current context.

#include <ptview/probes/WarpProbe.h>
#include <ptview/probes/WarpView.h>

#include <glm/glm.hpp>

namespace ptview {

class WarpVisualizer {
public:
    explicit WarpVisualizer(const WarpRequest& initial);

    bool active() const { return active_; }
    void setActive(bool active) { active_ = active; }

    // The controls (into the current window), and the mouse when no panel wants it: drag to
    // orbit, wheel to zoom.
    void drawControls();
    void handleMouse();
    // The points into `area` of the framebuffer (origin at the lower left, as OpenGL counts),
    // then, through ImGui's foreground list, the labelled axes and a caption over it;
    // pixelsPerPoint converts framebuffer pixels to ImGui's coordinates (HiDPI).
    void draw(glm::ivec2 areaOrigin, glm::ivec2 areaSize, glm::ivec2 framebufferSize, glm::vec2 pixelsPerPoint);
    void drawLabels(); // after ImGui::NewFrame: what draw() measured

private:
    WarpProbe probe_;
    WarpView view_;
    WarpRequest request_;
    OrbitCamera camera_;
    float coneAngleDeg_ = 60.0f;
    bool active_ = false;
    bool dirty_ = true;
    // Where draw() put the image, in ImGui coordinates (top-left origin), for drawLabels.
    glm::vec2 labelOrigin_{0.0f}, labelSize_{1.0f};
};

} // namespace ptview
