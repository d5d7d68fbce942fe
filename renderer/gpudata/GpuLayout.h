#pragma once
// C++ mirrors of GPU data layouts. Each must match its GLSL declaration byte for byte.
//
// Integers inside float texels (kinds, indices) are stored as float VALUES, not bit patterns: the
// bits of a small integer read as a float are a denormal, which a GPU may flush to zero on the
// way through an RGBA32F texture. A float holds every integer up to 2^24 exactly, which bounds
// what such a field may count (16.7 million triangles, nodes, lights).

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace ptview {

// The per-frame values of every pass: the std140 uniform block FrameBlock, whose GLSL
// (frame_uniforms.glsl) is generated from kFrameBlockFields below, so C++ writes each field at
// the offset GLSL reads it from. alignas(16): std140 rounds a block up to a whole vec4.
struct alignas(16) FrameUniforms {
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
    std::uint32_t samplerMode; // SamplerMode
    std::uint32_t sampleBudget;
    float sceneRadius;
    float apertureRadius;
    float focusDistance;
    float radianceClamp;
    std::int32_t lightPathBounces;
    std::uint32_t samplesPerPass;
};
static_assert(sizeof(FrameUniforms) == 128, "eight vec4 slots");

// One member of a std140 uniform block: its GLSL declaration and where C++ keeps it.
struct UniformField {
    std::string_view glslType; // float, int, uint, ivec2 or vec3
    const char* name;
    std::size_t offset;
    std::size_t size;
    const char* comment; // for the generated GLSL; "" for none
};

// One field: its GLSL type and name, the FrameUniforms member that holds it, and what it means.
#define PTVIEW_FRAME_FIELD(glslType, glslName, member, comment) \
    UniformField{glslType, glslName, offsetof(FrameUniforms, member), sizeof(FrameUniforms::member), comment}
// FrameBlock, in declaration order; what each value means is said here once, for both sides.
inline constexpr UniformField kFrameBlockFields[] = {
    PTVIEW_FRAME_FIELD("vec3", "uCameraEye", cameraEye, ""),
    PTVIEW_FRAME_FIELD("float", "uTanHalfFovY", tanHalfFovY, ""),
    PTVIEW_FRAME_FIELD("vec3", "uCameraRight", cameraRight, ""),
    PTVIEW_FRAME_FIELD("float", "uAspect", aspect, "width / height"),
    PTVIEW_FRAME_FIELD("vec3", "uCameraUp", cameraUp, ""),
    PTVIEW_FRAME_FIELD("uint", "uFrameIndex", frameIndex, "samples already accumulated"),
    PTVIEW_FRAME_FIELD("vec3", "uCameraForward", cameraForward, ""),
    PTVIEW_FRAME_FIELD("uint", "uSeed", seed, ""),
    PTVIEW_FRAME_FIELD("vec3", "uEnvironmentRadiance", environmentRadiance, ""),
    PTVIEW_FRAME_FIELD("int", "uMaxDepth", maxDepth, "bounces; 0 shows emitters only"),
    PTVIEW_FRAME_FIELD("ivec2", "uImageSize", imageSize, ""),
    PTVIEW_FRAME_FIELD("uint", "uSamplerMode", samplerMode, "SamplerMode; see sampler.glsl"),
    PTVIEW_FRAME_FIELD("uint", "uSampleBudget", sampleBudget,
                       "samples per pixel the grid and stratified patterns are sized for"),
    PTVIEW_FRAME_FIELD("float", "uSceneRadius", sceneRadius,
                       "of the scene's bounding sphere: sets ray offsets (intersect.glsl)"),
    PTVIEW_FRAME_FIELD("float", "uApertureRadius", apertureRadius,
                       "thin lens (camera_thin_lens.glsl), metres; 0: a pinhole"),
    PTVIEW_FRAME_FIELD("float", "uFocusDistance", focusDistance, "metres along the view direction"),
    PTVIEW_FRAME_FIELD("float", "uRadianceClamp", radianceClamp,
                       "largest component of one path vertex's contribution; 0: no clamp"),
    PTVIEW_FRAME_FIELD("int", "uLightPathBounces", lightPathBounces,
                       "k of the light-path views exactly / at most k (light_paths.glsl)"),
    PTVIEW_FRAME_FIELD("uint", "uSamplesPerPass", samplesPerPass,
                       "samples each pixel adds in this pass (pathtrace_sample.glsl)"),
};
#undef PTVIEW_FRAME_FIELD

namespace std140 {

constexpr std::size_t sizeOf(std::string_view glslType) {
    return glslType == "vec3" ? 12 : glslType == "ivec2" ? 8 : 4;
}
constexpr std::size_t alignmentOf(std::string_view glslType) {
    return glslType == "vec3" ? 16 : glslType == "ivec2" ? 8 : 4;
}
constexpr std::size_t roundUp(std::size_t n, std::size_t alignment) { return (n + alignment - 1) / alignment * alignment; }

// Whether GLSL, placing `fields` one after another by the std140 rules, puts each where C++ has
// it, and the block's size is `blockSize`: then no field of the C++ struct is left out either.
template <std::size_t N>
constexpr bool matches(const UniformField (&fields)[N], std::size_t blockSize) {
    std::size_t end = 0;
    for (const UniformField& field : fields) {
        if (field.size != sizeOf(field.glslType) || field.offset != roundUp(end, alignmentOf(field.glslType)))
            return false;
        end = field.offset + field.size;
    }
    return blockSize == roundUp(end, 16);
}

} // namespace std140

static_assert(std140::matches(kFrameBlockFields, sizeof(FrameUniforms)),
              "kFrameBlockFields must list FrameUniforms' members in order, at their std140 offsets");

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
static_assert(sizeof(GpuQuad) == 96, "six RGBA32F texels");

// Texels per record: record i of a buffer starts at texel kQuadTexels * i. These sizes are
// generated into the GLSL (gpu_layout.glsl), which never spells them.
constexpr int kQuadTexels = sizeof(GpuQuad) / 16;

struct GpuDisk {
    glm::vec3 center;
    float radius;
    glm::vec3 normal; // unit, the front side
    float pad;
};
static_assert(sizeof(GpuDisk) == 32, "two RGBA32F texels");
constexpr int kDiskTexels = sizeof(GpuDisk) / 16;

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
constexpr int kLightTexels = sizeof(GpuLight) / 16;

// shaders/scene_data.glsl: twelve RGBA32F texels per material. Texture indices are into
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
    // The medium (shaders/media.glsl): read only by programs of scenes with one.
    glm::vec3 sigmaA;
    float g;
    glm::vec3 sigmaS;
    float boundsMedium; // 1: crossing the surface changes the medium (Material::boundsMedium)
};
static_assert(sizeof(GpuMaterial) == 192, "twelve RGBA32F texels");
constexpr int kMaterialTexels = sizeof(GpuMaterial) / 16;

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
constexpr int kTextureRecordTexels = sizeof(GpuTextureRecord) / 16;

// shaders/mesh_intersect.glsl: a node of a four-wide BVH (renderer/geometry/WideBvh.h) as four
// RGBA32UI texels, its children's boxes quantized to a byte per plane (BvhNodePacking.h): a
// visit reads four texels for four boxes. Unlike the float buffers above, this one is integer,
// so its floats travel as their bits and its integers need no float values.
struct GpuBvhNode {
    glm::vec3 origin;        // the children's boxes' smallest corner (float bits)
    std::uint32_t exponents; // per axis, byte 0 x, 1 y, 2 z: a plane's step is 2^(e - 127)
    std::uint32_t childMinX; // child c's byte in bits 8c..8c+7: its min x is origin.x + q * step.x
    std::uint32_t childMaxX;
    std::uint32_t childMinY;
    std::uint32_t childMaxY;
    std::uint32_t childMinZ;
    std::uint32_t childMaxZ;
    std::uint32_t pad[2];
    std::uint32_t child[4];  // kBvhNoChild, kBvhLeafBit | first << 3 | (count - 1), or a node's index
};
static_assert(sizeof(GpuBvhNode) == 64, "four RGBA32UI texels");
constexpr std::uint32_t kBvhNoChild = 0xffffffffu;
constexpr std::uint32_t kBvhLeafBit = 0x80000000u;
constexpr int kBvhNodeTexels = sizeof(GpuBvhNode) / 16;

// shaders/mesh_intersect.glsl: seven RGBA32F texels per triangle, in the order of its mesh's BVH
// leaves (so a leaf's triangles are contiguous), uploaded as two arrays: the first four texels of
// every triangle (the corners and material slot, which the intersection loop reads, and a last
// texel that fills the record to 64 bytes, one cache line), then from kTrianglePositionTexels *
// triangles on the last three of every triangle (what only the closest hit reads), so that a
// leaf's corners lie together in memory. Records of 64 bytes start on a cache line: a triangle's
// corners are then one line, never two, as GPUs' memory systems want too. On llvmpipe that is
// worth little, 0.3% to 1.3% in time on the mesh scenes against 48-byte records
// (docs/performance.md, issue 35); the filler holds three of the uvs, which the closest hit reads
// with the corners anyway, so it costs no memory.
// Triangles of meshes that a normal-mapped material covers have three more texels, after all
// triangles in the same buffer: the corners' tangents (xyz unit, w the bitangent's sign:
// MeshTangents.h); other meshes carry none.
struct GpuTriangle {
    glm::vec3 p0;
    float materialSlot; // into the instance's material table (an integer value: GpuLayout.h)
    glm::vec3 p1;
    float tangentTexel; // first of the triangle's three tangent texels in the buffer; -1: none
    glm::vec3 p2;
    float pad1;
    glm::vec4 v1U2V2;   // (v1, u2, v2, -): the rest of the texture coordinates below
    glm::vec4 n0AndU0;  // per-corner shading normals (0: none, use the geometric normal) and
    glm::vec4 n1AndV0;  // texture coordinates (0 when the mesh has none)
    glm::vec4 n2AndU1;
};
static_assert(sizeof(GpuTriangle) == 112, "seven RGBA32F texels");
constexpr int kTriangleTexels = sizeof(GpuTriangle) / 16;
// Generated into gpu_layout.glsl.
constexpr int kTrianglePositionTexels = offsetof(GpuTriangle, n0AndU0) / 16;
static_assert(kTrianglePositionTexels * 16 == 64, "a triangle's corners fill one cache line");
constexpr int kTriangleAttributeTexels = kTriangleTexels - kTrianglePositionTexels;

// Texels per instance: world-to-object and object-to-world rows (three each), (bottom-level root,
// first triangle, material table offset, first light or -1), and a spare texel (uploadInstances).
constexpr int kInstanceTexels = 8;

} // namespace ptview
