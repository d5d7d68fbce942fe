#include <ptview/commands/PathsPicture.h>

#include <algorithm>
#include <cmath>

namespace ptview {
namespace {

struct CameraBasis {
    glm::vec3 eye, forward, right, up;
    float tanHalfFovY;
};

// The renderer's pinhole camera (PathTracer::updateFrameUniforms, shaders/camera.glsl).
CameraBasis basisOf(const CameraDesc& camera) {
    const CameraFrame frame = cameraFrame(camera);
    CameraBasis b;
    b.eye = camera.eye;
    b.forward = frame.forward;
    b.right = frame.right;
    b.up = frame.up;
    b.tanHalfFovY = std::tan(glm::radians(camera.vfovDeg) * 0.5f);
    return b;
}

glm::vec2 projectInFront(const CameraBasis& b, glm::ivec2 size, glm::vec3 point) {
    const glm::vec3 d = point - b.eye;
    const float z = glm::dot(d, b.forward);
    const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
    const float ndcX = glm::dot(d, b.right) / (z * b.tanHalfFovY * aspect);
    const float ndcY = glm::dot(d, b.up) / (z * b.tanHalfFovY);
    return {(ndcX + 1.0f) * 0.5f * static_cast<float>(size.x), (1.0f - ndcY) * 0.5f * static_cast<float>(size.y)};
}

class Canvas {
public:
    explicit Canvas(ImageRgba8& image) : image_(image) {}

    void blend(int x, int y, glm::u8vec3 color, float alpha) {
        if (x < 0 || y < 0 || x >= image_.width || y >= image_.height) return;
        std::uint8_t* p = &image_.rgba[(static_cast<size_t>(y) * static_cast<size_t>(image_.width) + static_cast<size_t>(x)) * 4];
        for (int c = 0; c < 3; ++c) p[c] = static_cast<std::uint8_t>(std::lround(p[c] + alpha * (color[c] - p[c])));
    }

    // A line two pixels wide, clipped to the image first (Liang-Barsky) so a segment that
    // projects far outside costs nothing.
    void line(glm::vec2 a, glm::vec2 b, glm::u8vec3 color) {
        float t0 = 0.0f, t1 = 1.0f;
        const glm::vec2 d = b - a;
        const float lo[2] = {-2.0f, -2.0f};
        const float hi[2] = {static_cast<float>(image_.width) + 2.0f, static_cast<float>(image_.height) + 2.0f};
        for (int axis = 0; axis < 2; ++axis) {
            for (int side = 0; side < 2; ++side) {
                const float p = side == 0 ? -d[axis] : d[axis];
                const float q = side == 0 ? a[axis] - lo[axis] : hi[axis] - a[axis];
                if (p == 0.0f) {
                    if (q < 0.0f) return;
                    continue;
                }
                const float r = q / p;
                if (p < 0.0f) t0 = std::max(t0, r);
                else t1 = std::min(t1, r);
            }
        }
        if (t0 > t1) return;
        const glm::vec2 from = a + t0 * d, to = a + t1 * d;
        const int steps = std::max(1, static_cast<int>(std::ceil(std::max(std::abs(to.x - from.x), std::abs(to.y - from.y)))));
        for (int i = 0; i <= steps; ++i) {
            const glm::vec2 p = from + (to - from) * (static_cast<float>(i) / static_cast<float>(steps));
            const int x = static_cast<int>(std::floor(p.x - 0.5f)), y = static_cast<int>(std::floor(p.y - 0.5f));
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx) blend(x + dx, y + dy, color, 0.85f);
        }
    }

    void dot(glm::vec2 p, glm::u8vec3 color) {
        const int x = static_cast<int>(std::floor(p.x)), y = static_cast<int>(std::floor(p.y));
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx) blend(x + dx, y + dy, std::abs(dx) == 2 || std::abs(dy) == 2 ? glm::u8vec3(0) : color, 1.0f);
    }

private:
    ImageRgba8& image_;
};

} // namespace

glm::u8vec3 pathSegmentColor(PathSegment kind) {
    switch (kind) {
    case PathSegment::Camera: return {255, 255, 255};
    case PathSegment::Bsdf: return {60, 170, 255};
    case PathSegment::ShadowReached: return {255, 215, 0};
    case PathSegment::ShadowBlocked: return {230, 40, 40};
    case PathSegment::Escaped: return {220, 90, 255};
    }
    return {0, 0, 0};
}

std::optional<glm::u8vec3> pathVertexColor(PathVertex::Kind kind) {
    switch (kind) {
    case PathVertex::Kind::Surface: return glm::u8vec3(255, 255, 255);
    case PathVertex::Kind::Medium: return glm::u8vec3(40, 230, 120);
    case PathVertex::Kind::Camera:
    case PathVertex::Kind::Escaped: return std::nullopt;
    }
    return std::nullopt;
}

CameraDesc sideViewCamera(const CameraDesc& camera, std::optional<glm::vec3> eye) {
    CameraDesc view = camera;
    view.apertureRadius = 0.0f; // a sharp picture, whatever the scene's lens
    if (eye) {
        view.eye = *eye;
        return view;
    }
    // Rodrigues' rotation of the eye about the up axis through the target.
    const glm::vec3 k = glm::normalize(camera.up);
    const glm::vec3 v = camera.eye - camera.target;
    const float angle = glm::radians(kSideViewDegrees);
    const glm::vec3 rotated = v * std::cos(angle) + glm::cross(k, v) * std::sin(angle) + k * glm::dot(k, v) * (1.0f - std::cos(angle));
    view.eye = camera.target + rotated;
    return view;
}

std::vector<PathLine> pathLines(const RecordedPath& path, float escapeLength) {
    std::vector<PathLine> lines;
    for (size_t i = 0; i < path.vertices.size(); ++i) {
        const PathVertex& v = path.vertices[i];
        const int index = static_cast<int>(i);
        if (v.kind == PathVertex::Kind::Escaped) {
            const glm::vec3 from = path.vertices[i - 1].position;
            lines.push_back({from, from + escapeLength * v.direction, PathSegment::Escaped, index - 1});
            continue;
        }
        if (i > 0)
            lines.push_back({path.vertices[i - 1].position, v.position, i == 1 ? PathSegment::Camera : PathSegment::Bsdf, index - 1});
        if (!v.shadowTraced) continue;
        const PathSegment kind = v.shadowBlocked ? PathSegment::ShadowBlocked : PathSegment::ShadowReached;
        if (v.lightAtInfinity) { // toward a light at infinity: as far as an escape is drawn
            lines.push_back({v.position, v.position + escapeLength * v.lightPoint, kind, index});
            continue;
        }
        glm::vec3 to = v.lightPoint;
        if (v.shadowBlocked && v.shadowHitDistance > 0.0f) to = v.position + glm::normalize(v.lightPoint - v.position) * v.shadowHitDistance;
        lines.push_back({v.position, to, kind, index});
    }
    return lines;
}

std::optional<std::pair<glm::vec2, glm::vec2>> projectSegment(const CameraDesc& camera, glm::ivec2 size, glm::vec3 from,
                                                              glm::vec3 to) {
    const CameraBasis b = basisOf(camera);
    const float nearZ = 1e-3f * glm::length(camera.target - camera.eye);
    const float za = glm::dot(from - b.eye, b.forward), zb = glm::dot(to - b.eye, b.forward);
    if (za < nearZ && zb < nearZ) return std::nullopt;
    if (za < nearZ) from = from + (to - from) * ((nearZ - za) / (zb - za));
    if (zb < nearZ) to = to + (from - to) * ((nearZ - zb) / (za - zb));
    return std::make_pair(projectInFront(b, size, from), projectInFront(b, size, to));
}

std::optional<glm::vec2> projectToImage(const CameraDesc& camera, glm::ivec2 size, glm::vec3 point) {
    const CameraBasis b = basisOf(camera);
    if (glm::dot(point - b.eye, b.forward) <= 0.0f) return std::nullopt;
    return projectInFront(b, size, point);
}

ImageRgba8 drawPathsPicture(PathTracer& tracer, const CameraDesc& view, const std::vector<RecordedPath>& paths,
                            int spp, const DisplaySettings& display, float escapeLength) {
    tracer.setCamera(view);
    tracer.renderSamples(spp);
    ImageRgba8 image = tracer.readToneMapped(display);
    const glm::ivec2 size(image.width, image.height);
    Canvas canvas(image);

    // Shadow rays first, under the path itself; the vertices last, on top.
    for (int pass = 0; pass < 2; ++pass)
        for (const RecordedPath& path : paths)
            for (const PathLine& line : pathLines(path, escapeLength)) {
                const bool shadow = line.kind == PathSegment::ShadowReached || line.kind == PathSegment::ShadowBlocked;
                if (shadow != (pass == 0)) continue;
                if (auto projected = projectSegment(view, size, line.from, line.to))
                    canvas.line(projected->first, projected->second, pathSegmentColor(line.kind));
            }
    for (const RecordedPath& path : paths)
        for (const PathVertex& v : path.vertices)
            if (std::optional<glm::u8vec3> color = pathVertexColor(v.kind))
                if (std::optional<glm::vec2> p = projectToImage(view, size, v.position)) canvas.dot(*p, *color);
    return image;
}

} // namespace ptview
