#pragma once
// The first surface a camera ray meets, as the GPU's own intersection code finds it
// (PathTracer::probeSurface, shaders/surface_probe.frag): what the pixel inspector shows and
// click-to-focus measures.

#include <glm/glm.hpp>

namespace ptview {

// The kind of primitive the GPU intersected; generated as kPrimitive* into gpu_layout.glsl.
enum class PrimitiveKind : int { Sphere = 0, Quad = 1, Disk = 2, MeshInstance = 3 };

struct SurfaceHit {
    float distance = 0.0f;     // along the ray, from the eye
    float viewDistance = 0.0f; // along the camera's view direction (what the focus distance measures)
    glm::vec3 position{0.0f};
    glm::vec3 normalGeom{0.0f};    // unit: a sphere's outward normal, a quad's cross(u, v), a triangle's winding
    glm::vec3 normalShading{0.0f}; // unit: what the BSDF is oriented by (interpolated, normal mapped)
    int material = -1;             // into Scene::materials
    PrimitiveKind primitiveKind = PrimitiveKind::Sphere;
    int primitive = -1; // index among the GPU's primitives of that kind (a box is six quads)
    int shape = -1;     // into Scene::shapes (shapeOfPrimitive), -1 when unknown
    glm::vec2 uv{0.0f}; // texture coordinates; 0 in programs without textures
};

} // namespace ptview
