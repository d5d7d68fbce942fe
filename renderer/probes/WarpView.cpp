#include <ptview/probes/WarpView.h>

#include <ptview/gl/Readback.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace ptview {
namespace {

const glm::vec3 kOutlineColor(0.55f, 0.55f, 0.6f);
const glm::vec3 kTriangleCorners[3] = {{-1.0f, -0.577f, 0.0f}, {1.0f, -0.577f, 0.0f}, {0.0f, 1.155f, 0.0f}};

// Segments along center + cos(t) a + sin(t) b for t from t0 to t1 (radians).
void appendArc(std::vector<glm::vec3>& lines, glm::vec3 center, glm::vec3 a, glm::vec3 b, float t0, float t1) {
    const int segments = std::max(8, static_cast<int>(std::ceil(96.0f * std::abs(t1 - t0) / 6.2831853f)));
    for (int i = 0; i < segments; ++i) {
        float s0 = t0 + (t1 - t0) * static_cast<float>(i) / segments, s1 = t0 + (t1 - t0) * static_cast<float>(i + 1) / segments;
        lines.push_back(center + std::cos(s0) * a + std::sin(s0) * b);
        lines.push_back(center + std::cos(s1) * a + std::sin(s1) * b);
    }
}

void appendCircle(std::vector<glm::vec3>& lines, glm::vec3 center, glm::vec3 a, glm::vec3 b) {
    appendArc(lines, center, a, b, 0.0f, 6.2831853f);
}

} // namespace

std::vector<glm::vec3> warpOutline(WarpDomain domain, float lowestCosTheta) {
    std::vector<glm::vec3> lines;
    const glm::vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    switch (domain) {
    case WarpDomain::Square: {
        const glm::vec3 corners[4] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
        for (int i = 0; i < 4; ++i) lines.insert(lines.end(), {corners[i], corners[(i + 1) % 4]});
        break;
    }
    case WarpDomain::Disk:
        appendCircle(lines, glm::vec3(0.0f), x, y);
        break;
    case WarpDomain::Triangle:
        for (int i = 0; i < 3; ++i) lines.insert(lines.end(), {kTriangleCorners[i], kTriangleCorners[(i + 1) % 3]});
        break;
    case WarpDomain::Sphere: {
        float cosThetaRim = glm::clamp(lowestCosTheta, -1.0f, 1.0f);
        float thetaRim = std::acos(cosThetaRim);
        // Two meridians, from the rim on one side over +z to the rim on the other (t is theta, from +z).
        appendArc(lines, glm::vec3(0.0f), z, x, -thetaRim, thetaRim);
        appendArc(lines, glm::vec3(0.0f), z, y, -thetaRim, thetaRim);
        if (cosThetaRim > -1.0f) { // the rim: the hemisphere's equator, the cone's edge
            float sinThetaRim = std::sqrt(std::max(0.0f, 1.0f - cosThetaRim * cosThetaRim));
            appendCircle(lines, cosThetaRim * z, sinThetaRim * x, sinThetaRim * y);
        }
        if (cosThetaRim < 0.0f) appendCircle(lines, glm::vec3(0.0f), x, y); // the equator, inside the support
        lines.insert(lines.end(), {glm::vec3(0.0f), 1.3f * z}); // the warp's axis, +z
        break;
    }
    }
    return lines;
}

float lowestCosTheta(const WarpRequest& request) {
    switch (request.warp) {
    case Warp::UniformCone: return request.cosThetaMax;
    case Warp::UniformHemisphere:
    case Warp::CosineHemisphere: return 0.0f;
    default: return -1.0f;
    }
}

std::string warpSupportText(const WarpRequest& request) {
    switch (request.warp) {
    case Warp::Square: return "points in the unit square";
    case Warp::UniformDiskPolar:
    case Warp::UniformDiskConcentric: return "points in the unit disk";
    case Warp::UniformSphere: return "directions on the whole sphere";
    case Warp::UniformCone: {
        char text[64];
        std::snprintf(text, sizeof text, "directions within %.3g deg of +z",
                      glm::degrees(std::acos(glm::clamp(request.cosThetaMax, -1.0f, 1.0f))));
        return text;
    }
    case Warp::UniformHemisphere:
    case Warp::CosineHemisphere: return "directions on the upper hemisphere (z >= 0)";
    case Warp::UniformTriangle: return "points in a triangle (barycentrics)";
    case Warp::HenyeyGreenstein: {
        char text[96];
        std::snprintf(text, sizeof text, "directions about +z, the direction of travel, mean cosine g = %.3g", request.g);
        return text;
    }
    }
    return "?";
}

glm::mat4 OrbitCamera::viewProjection(float aspect) const {
    float yaw = glm::radians(yawDeg), pitch = glm::radians(glm::clamp(pitchDeg, -89.0f, 89.0f));
    glm::vec3 eye = distance * glm::vec3(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch));
    glm::mat4 view = glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f));
    return glm::perspective(glm::radians(40.0f), aspect, 0.05f, 100.0f) * view;
}

OrbitCamera defaultWarpCamera(WarpDomain domain) {
    if (domain == WarpDomain::Sphere) return OrbitCamera{-60.0f, 30.0f, 4.2f};
    return OrbitCamera{};
}

glm::vec3 displayPosition(WarpDomain domain, glm::vec3 point) {
    if (domain == WarpDomain::Square) return glm::vec3(2.0f * glm::vec2(point) - 1.0f, 0.0f);
    if (domain == WarpDomain::Triangle)
        return point.x * kTriangleCorners[0] + point.y * kTriangleCorners[1] + (1.0f - point.x - point.y) * kTriangleCorners[2];
    return point;
}

WarpView::WarpView(const std::filesystem::path& shaderDir) {
    ShaderAssembler assembler(shaderDir);
    program_ = std::make_unique<GlProgram>(assembler.assemble("warp_points.vert"), assembler.assemble("warp_points.frag"));
    viewProjectionLocation_ = program_->uniformLocation("uViewProjection");
    pointSizeLocation_ = program_->uniformLocation("uPointSize");
    roundPointsLocation_ = program_->uniformLocation("uRoundPoints");
    cameraDistanceLocation_ = program_->uniformLocation("uCameraDistance");
    pointArray_ = createVertexArray();
    outlineArray_ = createVertexArray();
    pointBuffer_ = createBuffer();
    outlineBuffer_ = createBuffer();
}

void WarpView::upload(GlVertexArray& vertexArray, GlBuffer& buffer, const std::vector<Vertex>& vertices) {
    glBindVertexArray(vertexArray.id());
    glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)), vertices.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, color)));
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void WarpView::setSamples(const WarpRequest& request, const std::vector<WarpSample>& samples) {
    const WarpDomain domain = warpInfo(request.warp).domain;
    std::vector<Vertex> points;
    points.reserve(samples.size());
    for (const WarpSample& sample : samples)
        points.push_back({displayPosition(domain, sample.point), glm::vec3(sample.u, 0.35f) * 0.85f + 0.15f});
    upload(pointArray_, pointBuffer_, points);
    pointCount_ = static_cast<GLsizei>(points.size());

    std::vector<Vertex> lines;
    for (glm::vec3 p : warpOutline(domain, lowestCosTheta(request))) lines.push_back({p, kOutlineColor});
    upload(outlineArray_, outlineBuffer_, lines);
    outlineCount_ = static_cast<GLsizei>(lines.size());
}

void WarpView::draw(glm::ivec2 origin, glm::ivec2 viewportSize, const OrbitCamera& camera) const {
    viewportSize = glm::max(viewportSize, glm::ivec2(1));
    glViewport(origin.x, origin.y, viewportSize.x, viewportSize.y);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST); // points are sparse; depth would hide the far side of the sphere
    glDisable(GL_FRAMEBUFFER_SRGB);
    glEnable(GL_PROGRAM_POINT_SIZE);
    glEnable(GL_SCISSOR_TEST); // the clear respects the scissor, not the viewport
    glScissor(origin.x, origin.y, viewportSize.x, viewportSize.y);
    glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);

    glUseProgram(program_->id());
    glm::mat4 viewProjection = camera.viewProjection(static_cast<float>(viewportSize.x) / static_cast<float>(viewportSize.y));
    glUniformMatrix4fv(viewProjectionLocation_, 1, GL_FALSE, glm::value_ptr(viewProjection));
    glUniform1f(cameraDistanceLocation_, camera.distance);
    glUniform1i(roundPointsLocation_, 0);
    glBindVertexArray(outlineArray_.id());
    glDrawArrays(GL_LINES, 0, outlineCount_);

    // Fewer points can be bigger; keep dense sets readable.
    float pointSize = glm::clamp(600.0f / std::sqrt(static_cast<float>(std::max(pointCount_, 1))), 1.5f, 9.0f) *
                      static_cast<float>(viewportSize.y) / 800.0f;
    glUniform1f(pointSizeLocation_, std::max(pointSize, 1.0f));
    glUniform1i(roundPointsLocation_, 1);
    glBindVertexArray(pointArray_.id());
    glDrawArrays(GL_POINTS, 0, pointCount_);
    glBindVertexArray(0);
    glDisable(GL_PROGRAM_POINT_SIZE);
    glDisable(GL_SCISSOR_TEST);
}

ImageRgba8 WarpView::renderImage(glm::ivec2 size, const OrbitCamera& camera) const {
    return renderOffscreenRgba8(size, [&](glm::ivec2 viewportSize) { draw(viewportSize, camera); });
}

} // namespace ptview
