#pragma once
// Watertight ray-triangle intersection: Woop, Benthin and Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2(1), 2013. The ray is made the +z axis of a sheared frame in which the
// edge functions U, V, W are 2D cross products of the vertices' projected positions. A vertex
// projects to the same (x, y) whichever triangle it belongs to, and fl(a*b - c*d) is exactly
// -fl(c*d - a*b), so two triangles sharing an edge see exactly opposite values of its edge
// function: a ray through the edge hits at least one of them. No backface culling.
//
// The GLSL version (shaders) mirrors this function line for line, except that it
//   - drops the double-precision recomputation of U, V, W (GLSL 4.10 has doubles, but they are
//     slow on consumer GPUs; an exact 0 in float then only makes the test non-watertight on a
//     measure-zero set of rays),
//   - must declare ax..cy and u, v, w `precise`, or a driver may fuse a product into an FMA on one
//     triangle and not on its neighbour, which breaks the exact antisymmetry above.
// The same holds on the CPU: baseline x86-64 has no FMA, but a build for an FMA target must use
// -ffp-contract=off for this header's guarantee to hold (GCC contracts across statements).

#include <glm/glm.hpp>

#include <cmath>
#include <optional>
#include <utility>

namespace ptview {

// The per-ray constants, computed once per ray and shared by every triangle it is tested against.
struct WatertightRay {
    glm::vec3 origin;
    int kx, ky, kz;  // kz: the axis where |direction| is largest; kx, ky the other two
    float sx, sy, sz; // shear taking direction to (0, 0, 1) in the permuted frame
};

// `direction` must be non-zero; it need not be unit, and hits' t are in units of its length.
inline WatertightRay watertightRay(glm::vec3 origin, glm::vec3 direction) {
    glm::vec3 a = glm::abs(direction);
    int kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    int kx = (kz + 1) % 3;
    int ky = (kx + 1) % 3;
    // Swapping keeps the winding, hence the sign of U, V, W, the same whatever the sign of d[kz].
    if (direction[kz] < 0.0f) std::swap(kx, ky);
    WatertightRay ray;
    ray.origin = origin;
    ray.kx = kx;
    ray.ky = ky;
    ray.kz = kz;
    ray.sx = direction[kx] / direction[kz];
    ray.sy = direction[ky] / direction[kz];
    ray.sz = 1.0f / direction[kz];
    return ray;
}

struct TriangleHit {
    float t;
    glm::vec3 barycentric; // b0, b1, b2: weights of p0, p1, p2; sum to 1
};

// The hit of `ray` with triangle (p0, p1, p2) with t in (0, tMax), or none. Degenerate triangles
// and rays in the triangle's plane (determinant 0) miss.
inline std::optional<TriangleHit> intersectTriangle(const WatertightRay& ray, glm::vec3 p0,
                                                    glm::vec3 p1, glm::vec3 p2, float tMax) {
    const int kx = ray.kx, ky = ray.ky, kz = ray.kz;
    const glm::vec3 a = p0 - ray.origin;
    const glm::vec3 b = p1 - ray.origin;
    const glm::vec3 c = p2 - ray.origin;

    // Shear and scale into the ray's frame; z waits until we know the ray is inside.
    const float ax = a[kx] - ray.sx * a[kz];
    const float ay = a[ky] - ray.sy * a[kz];
    const float bx = b[kx] - ray.sx * b[kz];
    const float by = b[ky] - ray.sy * b[kz];
    const float cx = c[kx] - ray.sx * c[kz];
    const float cy = c[ky] - ray.sy * c[kz];

    // U is the edge function of the edge opposite p0, so it is p0's unnormalized weight.
    float u = cx * by - cy * bx;
    float v = ax * cy - ay * cx;
    float w = bx * ay - by * ax;

    // A zero may be a rounded-off sign: the products of floats are exact in double, and the one
    // rounding of their difference keeps its sign. (GLSL drops this.)
    if (u == 0.0f || v == 0.0f || w == 0.0f) {
        u = float(double(cx) * double(by) - double(cy) * double(bx));
        v = float(double(ax) * double(cy) - double(ay) * double(cx));
        w = float(double(bx) * double(ay) - double(by) * double(ax));
    }

    // Inside means all three on the same side, either side: no backface culling.
    if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f))
        return std::nullopt;
    const float det = u + v + w;
    if (det == 0.0f) return std::nullopt;

    const float az = ray.sz * a[kz];
    const float bz = ray.sz * b[kz];
    const float cz = ray.sz * c[kz];
    const float tScaled = u * az + v * bz + w * cz; // t * det

    // Reject t <= 0 from signs alone (exact) before paying for the division.
    if ((tScaled <= 0.0f && det > 0.0f) || (tScaled >= 0.0f && det < 0.0f)) return std::nullopt;
    const float invDet = 1.0f / det;
    const float t = tScaled * invDet;
    if (!(t > 0.0f && t < tMax)) return std::nullopt;
    return TriangleHit{t, glm::vec3(u, v, w) * invDet};
}

} // namespace ptview
