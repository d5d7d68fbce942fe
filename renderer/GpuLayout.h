#pragma once
// C++ mirrors of GPU data layouts. Each must match its GLSL declaration byte for byte.

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
    std::uint32_t pad0;
    std::uint32_t pad1;
    std::uint32_t pad2;
};
static_assert(sizeof(FrameUniforms) == 112, "FrameUniforms must match the std140 FrameBlock");

// shaders/scene_data.glsl: one texel (RGBA32F) of a buffer texture.
struct GpuSphere {
    glm::vec3 center;
    float radius;
};
static_assert(sizeof(GpuSphere) == 16, "one RGBA32F texel");

struct GpuQuad {
    glm::vec4 center; // w unused
    glm::vec4 u;
    glm::vec4 v;
    glm::vec4 dual;   // cross(u, v) / |cross(u, v)|^2, turns hit offsets into (a, b) coordinates
};
static_assert(sizeof(GpuQuad) == 64, "four RGBA32F texels");

struct GpuDisk {
    glm::vec3 center;
    float radius;
    glm::vec3 normal; // unit, the front side
    float pad;
};
static_assert(sizeof(GpuDisk) == 32, "two RGBA32F texels");

// Per primitive (RG32I): its material and, when it emits, its light index (else -1).
struct GpuPrimitiveIds {
    std::int32_t material;
    std::int32_t light;
};
static_assert(sizeof(GpuPrimitiveIds) == 8, "one RG32I texel");

// shaders/lights.glsl: four RGBA32F texels per light; kind and primitive are stored as the bits
// of unsigned integers (read back with floatBitsToUint).
struct GpuLight {
    std::uint32_t kind;      // LightKind
    std::uint32_t primitive; // index among the quads, spheres or disks; unused otherwise
    std::uint32_t pad0;
    std::uint32_t pad1;
    glm::vec3 position;      // point and spot
    float cosInner;          // spot: full intensity where cos(angle to axis) >= cosInner
    glm::vec3 direction;     // spot: unit axis
    float cosOuter;          // spot: nothing where cos(angle to axis) <= cosOuter
    glm::vec3 intensity;     // point and spot: W sr^-1
    float pad2;
};
static_assert(sizeof(GpuLight) == 64, "four RGBA32F texels");

struct GpuMaterialParams {
    glm::vec3 color;
    float ior;
    glm::vec3 radiance;
    float roughness;
};
static_assert(sizeof(GpuMaterialParams) == 32, "two RGBA32F texels");

} // namespace ptview
