#pragma once
// C++ mirrors of GPU data layouts. Each must match its GLSL declaration byte for byte.
//
// Integers inside float texels (kinds, indices) are stored as float VALUES, not bit patterns: the
// bits of a small integer read as a float are a denormal, which a GPU may flush to zero on the
// way through an RGBA32F texture. A float holds every integer up to 2^24 exactly, which bounds
// what such a field may count (16.7 million triangles, nodes, lights).

#include <glm/glm.hpp>

#include <cstdint>

namespace ptview {

// shaders/frame_uniforms.glsl, std140: a vec3 and the scalar after it share one 16-byte slot.
struct FrameUniforms {
    glm::vec3 cameraEye;
    float tanHalfFovY;
    glm::vec3 cameraRight;
    float aspect;
    glm::vec3 cameraUp;
    std::uint32_t frameIndex;
    glm::vec3 cameraForward;
    std::uint32_t seed;
    glm::vec3 environmentRadiance;
    std::int32_t maxDepth;
    glm::ivec2 imageSize;
    std::uint32_t samplerMode;  // SamplerMode
    std::uint32_t sampleBudget; // samples per pixel the grid and stratified patterns are sized for
    std::uint32_t integrator;   // Integrator
    float sceneRadius;          // bounding sphere of the geometry, for ray offsets (intersect.glsl)
    float apertureRadius;       // thin lens, metres; 0: a pinhole
    float focusDistance;        // metres along the view direction
    float radianceClamp;        // largest component of one path vertex's contribution; 0: no clamp
    std::int32_t lightPathBounces; // k of the light-path views exactly / at most k (light_paths.glsl)
    std::uint32_t samplesPerPass; // samples each pixel adds in one pass (pathtrace_sample.glsl)
    std::uint32_t pad3;
};
static_assert(sizeof(FrameUniforms) == 128, "FrameUniforms must match the std140 FrameBlock");

// shaders/scene_data.glsl: one texel (RGBA32F) of a buffer texture.
struct GpuSphere {
    glm::vec3 center;
    float radius;
};
static_assert(sizeof(GpuSphere) == 16, "one RGBA32F texel");

// The parallelogram center +- u +- v, and what its ray test needs precomputed (scene_data.glsl
// fetchQuad, intersect.glsl intersectQuad): with dual = normal / |normal|^2, the reciprocal basis
// reciprocalU = cross(v, dual), reciprocalV = cross(dual, u) turns a hit's offset from the center
// into its coordinates along u and v; the w's are magnitudes for the test's rounding bound.
struct GpuQuad {
    glm::vec4 center;      // w: max |component| of center
    glm::vec4 normal;      // cross(u, v), the front side; w unused
    glm::vec4 reciprocalU; // w: |x| + |y| + |z|
    glm::vec4 reciprocalV; // w: |x| + |y| + |z|
    glm::vec4 u;           // w unused
    glm::vec4 v;           // w unused
};
static_assert(sizeof(GpuQuad) == 96, "six RGBA32F texels (kQuadTexels)");

struct GpuDisk {
    glm::vec3 center;
    float radius;
    glm::vec3 normal; // unit, the front side
    float pad;
};
static_assert(sizeof(GpuDisk) == 32, "two RGBA32F texels");

// Per primitive (RG32I): its material and, when it emits, its light index (else -1). The
// spheres', quads' and disks' ids share one buffer, in that order.
struct GpuPrimitiveIds {
    std::int32_t material;
    std::int32_t light;
};
static_assert(sizeof(GpuPrimitiveIds) == 8, "one RG32I texel");

// shaders/lights.glsl: four RGBA32F texels per light. The first holds the kind, the primitive and
// the light's cumulative selection probability (the table is searched by it); the other three
// depend on the kind:
//   point, spot: (position, cosInner), (unit direction, cosOuter), (intensity W sr^-1, -)
//   triangle:    (v0, -), (v1, -), (v2, -) in world space; front side along cross(v1 - v0, v2 - v0)
//   quad, sphere, disk, environment: unused (the primitive's own data is read instead)
struct GpuLight {
    float kind;      // LightKind
    float primitive; // quad, sphere or disk: its index; triangle: its material
    float cdf;       // selection probability of this light and all before it
    float pad;
    glm::vec4 texels[3];
};
static_assert(sizeof(GpuLight) == 64, "four RGBA32F texels");

// shaders/scene_data.glsl: ten RGBA32F texels per material. Texture indices are into
// Scene::textures, -1 for none; slots (scale.xy, offset.xy) in the order base colour, roughness,
// metallic, normal, emission. The texture fields are read only by programs with textures.
struct GpuMaterial {
    glm::vec3 color;
    float ior;
    glm::vec3 radiance;
    float roughness;
    float type; // MaterialType
    float metallic;
    float transmission;
    float alpha;
    float alphaMode; // AlphaMode
    float alphaCutoff;
    float normalScale;
    float emissionTexture;
    glm::vec4 textures; // base colour, roughness, metallic, normal
    glm::vec4 slots[5];
};
static_assert(sizeof(GpuMaterial) == 160, "ten RGBA32F texels");

// shaders/textures.glsl: two RGBA32F texels per texture, after the materials in their buffer.
// Where the texture lies in the atlas (layer, texel origin, size) and how it is read.
struct GpuTextureRecord {
    float layer;
    float originX;
    float originY;
    float width;
    float height;
    float wrapU; // TextureWrap
    float wrapV;
    float flags; // 1: sRGB, 2: bilinear
};
static_assert(sizeof(GpuTextureRecord) == 32, "two RGBA32F texels");

} // namespace ptview
