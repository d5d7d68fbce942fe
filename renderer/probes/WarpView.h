#pragma once
// Draws warped sample points in 3D with the outline of their domain: the picture behind
// `ptview warp` and the viewer's warp visualizer. Points are coloured by the u that produced them
// (red along u.x, green along u.y), so one sees where each part of the square lands.

#include <ptview/gl/GlObjects.h>
#include <ptview/gl/GlProgram.h>
#include <ptview/io/Image.h>
#include <ptview/geometry/Warp.h>
#include <ptview/probes/WarpProbe.h>

#include <glm/glm.hpp>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace ptview {

// An orbit around the origin, +z up.
struct OrbitCamera {
    float yawDeg = -90.0f;
    float pitchDeg = 89.0f;
    float distance = 3.4f;

    glm::mat4 viewProjection(float aspect) const;
};

// Looking straight down at planar domains, from above and aside at spherical ones.
OrbitCamera defaultWarpCamera(WarpDomain domain);

// Where a warp's output is drawn: the square and triangle are mapped to shapes centred on the
// origin; disks and directions are drawn as they are.
glm::vec3 displayPosition(WarpDomain domain, glm::vec3 point);

// The lowest cos theta (z) a direction warp can produce: -1 for the sphere, 0 for the hemispheres,
// the cone's cosThetaMax; -1 for the planar domains, which have no theta.
float lowestCosTheta(const WarpRequest& request);

// What the view's outline draws, as line segments (pairs of points): the edge of the planar domains,
// and for directions the part of the unit sphere the warp can reach (its rim, and meridians from +z
// down to the rim), so a hemisphere warp is not drawn inside a whole sphere.
std::vector<glm::vec3> warpOutline(WarpDomain domain, float lowestCosTheta);

// Where the request's points land, in words for the view's caption: "directions on the upper
// hemisphere (z >= 0)", "directions within 60 deg of +z", "points in the unit disk".
std::string warpSupportText(const WarpRequest& request);

class WarpView {
public:
    explicit WarpView(const std::filesystem::path& shaderDir = PTVIEW_SHADER_DIR);

    // The points of request (from WarpProbe::sample) and the outline of where they can land.
    void setSamples(const WarpRequest& request, const std::vector<WarpSample>& samples);
    // Into the bound draw framebuffer, over the whole viewport.
    void draw(glm::ivec2 viewportSize, const OrbitCamera& camera) const { draw({0, 0}, viewportSize, camera); }
    // Into the rectangle at origin (lower left, framebuffer pixels) of that size, touching
    // nothing outside it (the viewer's image area, beside the sidebar).
    void draw(glm::ivec2 origin, glm::ivec2 size, const OrbitCamera& camera) const;
    // Offscreen, for headless pictures.
    ImageRgba8 renderImage(glm::ivec2 size, const OrbitCamera& camera) const;

private:
    struct Vertex {
        glm::vec3 position;
        glm::vec3 color;
    };
    static void upload(GlVertexArray& vertexArray, GlBuffer& buffer, const std::vector<Vertex>& vertices);

    std::unique_ptr<GlProgram> program_;
    GLint viewProjectionLocation_ = -1;
    GLint pointSizeLocation_ = -1;
    GLint roundPointsLocation_ = -1;
    GLint cameraDistanceLocation_ = -1;
    GlVertexArray pointArray_, outlineArray_;
    GlBuffer pointBuffer_, outlineBuffer_;
    GLsizei pointCount_ = 0;
    GLsizei outlineCount_ = 0;
};

} // namespace ptview
