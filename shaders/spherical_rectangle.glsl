// Sampling a rectangle by solid angle: the spherical rectangle it subtends from a point, sampled
// uniformly (Ureña, Fajardo and King, "An Area-Preserving Parametrization for Spherical
// Rectangles", EGSR 2013). Area sampling's solid-angle density is distance^2 / (cos * area),
// which varies a lot over a light that is close or seen at a slant; this density is 1 / solid
// angle everywhere on it, so the only variation left in a light sample is the BSDF's and the
// shading cosine's.
//
// The rectangle is expressed in its own frame: x and y along its edges, z along its normal turned
// so that the point lies on the negative side (z0 < 0), with the point at the origin.
#include "constants.glsl"

struct SphericalRectangle {
    vec3 x, y, z;       // the frame, world space, unit
    float x0, x1, y0, y1, z0; // the rectangle's extent in the frame, relative to the point; z0 <= 0
    float b0, b1, k;    // for the inversion (the paper's b0, b1 and k)
    float solidAngle;   // S; may be inaccurate or NaN where viewRectangleFrom says so
};

// corner: one corner of the rectangle; edgeX, edgeY: its two edges from that corner (orthogonal).
SphericalRectangle viewRectangleFrom(vec3 point, vec3 corner, vec3 edgeX, vec3 edgeY) {
    SphericalRectangle r;
    float lengthX = length(edgeX);
    float lengthY = length(edgeY);
    r.x = edgeX / lengthX;
    r.y = edgeY / lengthY;
    r.z = cross(r.x, r.y);
    vec3 d = corner - point;
    r.z0 = dot(d, r.z);
    if (r.z0 > 0.0) {
        r.z = -r.z;
        r.z0 = -r.z0;
    }
    r.x0 = dot(d, r.x);
    r.y0 = dot(d, r.y);
    r.x1 = r.x0 + lengthX;
    r.y1 = r.y0 + lengthY;
    // Normals of the four planes through the point and an edge (the sides of the spherical
    // rectangle), and the rectangle's inner angles between them.
    vec3 n0 = normalize(vec3(0.0, r.z0, -r.y0));
    vec3 n1 = normalize(vec3(-r.z0, 0.0, r.x1));
    vec3 n2 = normalize(vec3(0.0, -r.z0, r.y1));
    vec3 n3 = normalize(vec3(r.z0, 0.0, -r.x0));
    float g0 = acos(clamp(-dot(n0, n1), -1.0, 1.0));
    float g1 = acos(clamp(-dot(n1, n2), -1.0, 1.0));
    float g2 = acos(clamp(-dot(n2, n3), -1.0, 1.0));
    float g3 = acos(clamp(-dot(n3, n0), -1.0, 1.0));
    r.b0 = n0.z;
    r.b1 = n2.z;
    r.k = 2.0 * kPi - g2 - g3;
    // The angle excess: a difference of numbers near 2 pi, so float leaves an absolute error of a
    // few 1e-7 in it, whatever the solid angle (see kMinSphericalRectangleSolidAngle).
    r.solidAngle = g0 + g1 - r.k;
    return r;
}

// Below this solid angle (steradians) the angle excess has a relative error above about 1e-4 in
// float, and the density 1 / S would carry it as a bias; area sampling is used instead. Seen that
// small a light varies little over its extent in distance and slant, so area sampling is nearly
// as good there. Above the maximum (a point almost on the rectangle, which then fills nearly a
// hemisphere), the inversion's sines vanish and lose precision.
const float kMinSphericalRectangleSolidAngle = 1e-2;
const float kMaxSphericalRectangleSolidAngle = 6.2;

// Whether sampleSphericalRectangle is accurate for this view (false also for NaN, as from a point
// on the rectangle's plane).
bool sphericalRectangleUsable(SphericalRectangle r) {
    return r.solidAngle >= kMinSphericalRectangleSolidAngle && r.solidAngle <= kMaxSphericalRectangleSolidAngle;
}

// The point on the rectangle (world space, relative to the viewing point) whose direction is
// uniformly distributed over the spherical rectangle for u uniform on the unit square.
vec3 sampleSphericalRectangle(SphericalRectangle r, vec2 u) {
    // x: invert the area of the part of the spherical rectangle left of the plane through x.
    float au = u.x * r.solidAngle + r.k;
    float fu = (cos(au) * r.b0 - r.b1) / sin(au);
    float cu = clamp((fu >= 0.0 ? 1.0 : -1.0) * inversesqrt(fu * fu + r.b0 * r.b0), -1.0, 1.0);
    float xu = clamp(-(cu * r.z0) * inversesqrt(max(1.0 - cu * cu, 1e-12)), r.x0, r.x1);
    // y: uniform in the height h on the unit sphere along that line.
    float d = sqrt(xu * xu + r.z0 * r.z0);
    float h0 = r.y0 / sqrt(d * d + r.y0 * r.y0);
    float h1 = r.y1 / sqrt(d * d + r.y1 * r.y1);
    float hv = mix(h0, h1, u.y);
    float hv2 = hv * hv;
    float yv = hv2 < 1.0 - 1e-6 ? clamp(hv * d * inversesqrt(1.0 - hv2), r.y0, r.y1) : r.y1;
    return xu * r.x + yv * r.y + r.z0 * r.z;
}

// The solid-angle density of sampleSphericalRectangle for any direction that reaches the
// rectangle (uniform: it does not depend on the direction).
float sphericalRectanglePdf(SphericalRectangle r) {
    return 1.0 / r.solidAngle;
}
