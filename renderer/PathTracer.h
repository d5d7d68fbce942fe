#pragma once
// The progressive path tracer: one sample per pixel per pass into ping-ponged RGBA32F
// accumulation targets, and a display pass that tone maps the running mean. Used as-is by the
// headless renderer and the viewer; it needs a current OpenGL 4.1+ core context.

#include "Accumulator.h"
#include "GlObjects.h"
#include "EnvironmentMap.h"
#include "GlProgram.h"
#include "GpuEnvironmentMap.h"
#include "GpuScene.h"
#include "Image.h"
#include "Integrator.h"
#include "SamplerMode.h"
#include "Scene.h"

#include <cstdint>
#include <filesystem>
#include <memory>

namespace ptview {

struct RenderSettings {
    int maxDepth = 8;       // bounces; 0 shows only what the camera sees directly
    std::uint32_t seed = 0; // decorrelates independent renders of the same scene
    SamplerMode sampler = SamplerMode::Random;
    // The samples per pixel the render is heading for: grid and stratified lay out patterns of
    // n^2 <= sampleBudget samples, so a render of exactly that many is fully stratified.
    std::uint32_t sampleBudget = 1024;
    Integrator integrator = Integrator::Naive;

    bool operator==(const RenderSettings& other) const {
        return integrator == other.integrator && maxDepth == other.maxDepth && seed == other.seed && sampler == other.sampler &&
               sampleBudget == other.sampleBudget;
    }
    bool operator!=(const RenderSettings& other) const { return !(*this == other); }
};

class PathTracer {
public:
    // Compiles the programs. Throws ShaderError.
    explicit PathTracer(const std::filesystem::path& shaderDir = PTVIEW_SHADER_DIR);

    // Each of these restarts accumulation.
    // Reads scene.environmentMap unless the caller already has (environmentMap, to report a bad
    // file before any GPU work); throws EnvironmentMapError naming the file.
    void setScene(const Scene& scene, const EnvironmentMap* environmentMap = nullptr);
    // Live material edits (same count and order as the scene's): re-sent to the GPU as they are,
    // no shader is recompiled; the next sample already uses them.
    void setMaterials(const std::vector<Material>& materials);
    void setSettings(const RenderSettings& settings); // restarts only when something changed
    void setImageSize(glm::ivec2 size);               // restarts only when the size changed
    void restart() { accumulator_.restart(); }

    void renderSample();

    int sampleCount() const { return accumulator_.sampleCount(); }
    glm::ivec2 imageSize() const { return accumulator_.size(); }
    const RenderSettings& settings() const { return settings_; }

    // Draws the tone-mapped mean over the whole viewport of the bound draw framebuffer.
    void display(glm::ivec2 viewportSize, float exposureStops) const;

    ImageRgbF readMean() const;
    PixelStatistics readStatistics() const { return accumulator_.readStatistics(); }
    ImageRgba8 readToneMapped(float exposureStops) const;

private:
    void updateFrameUniforms();
    void setLightUniforms();

    std::unique_ptr<GlProgram> pathTraceProgram_;
    std::unique_ptr<GlProgram> displayProgram_;
    GLint sphereCountLocation_ = -1;
    GLint quadCountLocation_ = -1;
    GLint diskCountLocation_ = -1;
    GLint lightCountLocation_ = -1;
    GLint environmentLightLocation_ = -1;
    GLint invSampleCountLocation_ = -1;
    GLint exposureScaleLocation_ = -1;
    GLint outputSizeLocation_ = -1;

    GlVertexArray emptyVertexArray_; // core profile needs a VAO bound even without attributes
    GlBuffer frameUniformBuffer_;
    GpuScene gpuScene_;
    GpuEnvironmentMap environmentMap_;
    Accumulator accumulator_;

    CameraDesc camera_;
    glm::vec3 environmentRadiance_{0.0f};
    RenderSettings settings_;
};

} // namespace ptview
