#pragma once
// A CPU ray cast against a scene's analytic primitives (quads, boxes as their quads, spheres,
// disks), written from the shapes' definitions (docs/scene-format.md), not from the GLSL: what
// the tests check the GPU's intersections against. No meshes.
#include <ptview/gpu/GpuScene.h>
#include <ptview/scene/Scene.h>

#include <glm/glm.hpp>

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace ptview::testing {

struct CpuHit {
    float t = std::numeric_limits<float>::infinity();
    int material = -1;
};

class CpuRayCaster {
public:
    explicit CpuRayCaster(const Scene& scene)
        : geometry_(flattenScene(scene)), lights_(buildLightTable(geometry_, scene.materials, scene.environment).lights) {}

    // The nearest primitive along origin + t * direction (direction unit) with t in (tMin, tMax),
    // leaving out the primitive of light `skipLight` (an index into the GPU's light table) if any:
    // what a shadow ray toward that light asks.
    std::optional<CpuHit> nearest(glm::vec3 origin, glm::vec3 direction, float tMin, float tMax, int skipLight = -1) const {
        LightKind skipKind = LightKind::Environment;
        int skipPrimitive = -1;
        if (skipLight >= 0) {
            skipKind = static_cast<LightKind>(static_cast<std::uint32_t>(lights_.at(static_cast<size_t>(skipLight)).kind));
            skipPrimitive = static_cast<int>(lights_.at(static_cast<size_t>(skipLight)).primitive);
        }
        CpuHit best;
        best.t = tMax;
        LightKind kind = LightKind::Quad;
        int primitive = 0;
        auto consider = [&](float t, int material) {
            if (kind == skipKind && primitive == skipPrimitive) return;
            if (t > tMin && t < best.t) best = CpuHit{t, material};
        };
        kind = LightKind::Quad;
        for (size_t i = 0; i < geometry_.quads.size(); ++i) {
            primitive = static_cast<int>(i);
            const GpuQuad& q = geometry_.quads[i];
            glm::vec3 center(q.center), u(q.u), v(q.v);
            glm::vec3 n = glm::cross(u, v);
            float denom = glm::dot(direction, n);
            if (denom == 0.0f) continue;
            float t = glm::dot(center - origin, n) / denom;
            // Coordinates along u and v from the Gram matrix (u and v need not be orthogonal).
            glm::vec3 offset = origin + t * direction - center;
            float uu = glm::dot(u, u), uv = glm::dot(u, v), vv = glm::dot(v, v);
            float det = uu * vv - uv * uv;
            float a = (vv * glm::dot(offset, u) - uv * glm::dot(offset, v)) / det;
            float b = (uu * glm::dot(offset, v) - uv * glm::dot(offset, u)) / det;
            if (std::abs(a) <= 1.0f && std::abs(b) <= 1.0f) consider(t, geometry_.quadMaterials[i]);
        }
        kind = LightKind::Sphere;
        for (size_t i = 0; i < geometry_.spheres.size(); ++i) {
            primitive = static_cast<int>(i);
            const GpuSphere& s = geometry_.spheres[i];
            glm::vec3 f = origin - s.center;
            float b = glm::dot(f, direction);
            float c = glm::dot(f, f) - s.radius * s.radius;
            float discriminant = b * b - c;
            if (discriminant < 0.0f) continue;
            float root = std::sqrt(discriminant);
            consider(-b - root, geometry_.sphereMaterials[i]);
            consider(-b + root, geometry_.sphereMaterials[i]);
        }
        kind = LightKind::Disk;
        for (size_t i = 0; i < geometry_.disks.size(); ++i) {
            primitive = static_cast<int>(i);
            const GpuDisk& d = geometry_.disks[i];
            float denom = glm::dot(direction, d.normal);
            if (denom == 0.0f) continue;
            float t = glm::dot(d.center - origin, d.normal) / denom;
            glm::vec3 offset = origin + t * direction - d.center;
            if (glm::dot(offset, offset) <= d.radius * d.radius) consider(t, geometry_.diskMaterials[i]);
        }
        if (best.material < 0) return std::nullopt;
        return best;
    }

private:
    ScenePrimitives geometry_;
    std::vector<GpuLight> lights_;
};

} // namespace ptview::testing
