#pragma once
// The scene as GPU primitives: boxes become six quads, and everything goes into buffer textures
// that shaders/scene_data.glsl reads.

#include "GlObjects.h"
#include "GpuLayout.h"
#include "Scene.h"

#include <cstdint>
#include <vector>

namespace ptview {

struct ScenePrimitives {
    std::vector<GpuSphere> spheres;
    std::vector<std::uint32_t> sphereMaterials;
    std::vector<GpuQuad> quads;
    std::vector<std::uint32_t> quadMaterials;
    std::vector<GpuMaterialParams> materialParams;
    std::vector<std::uint32_t> materialTypes;
};

// Pure CPU steps, testable without a GL context.
ScenePrimitives flattenScene(const Scene& scene);
void flattenMaterials(const std::vector<Material>& materials, ScenePrimitives& out);

class GpuScene {
public:
    static constexpr int kTextureCount = 6;

    void upload(const Scene& scene);
    // Material edits only: no geometry is re-sent and nothing is recompiled.
    void uploadMaterials(const std::vector<Material>& materials);
    // Binds the buffer textures to units firstUnit .. firstUnit + kTextureCount - 1, in the order
    // spheres, sphere materials, quads, quad materials, material params, material types.
    void bind(int firstUnit) const;

    int sphereCount() const { return sphereCount_; }
    int quadCount() const { return quadCount_; }

private:
    struct BufferTexture {
        GlBuffer buffer;
        GlTexture texture;
    };
    BufferTexture textures_[kTextureCount];
    int sphereCount_ = 0;
    int quadCount_ = 0;
};

} // namespace ptview
