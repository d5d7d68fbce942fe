#include "PathTracer.h"

#include "GpuLayout.h"
#include "Readback.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace ptview {
namespace {

constexpr GLuint kFrameBlockBinding = 0;
constexpr int kAccumulationUnit = 0;                             // units 0..2
constexpr int kSceneUnit = kAccumulationUnit + Accumulator::kTextureCount; // units 3..12
constexpr int kEnvironmentUnit = 13; // units 13..15: the last that OpenGL 4.1 guarantees (16)
static_assert(kSceneUnit + GpuScene::kTextureCount <= kEnvironmentUnit, "texture units overlap");
static_assert(kEnvironmentUnit + GpuEnvironmentMap::kTextureCount <= 16, "OpenGL 4.1 guarantees 16 units");

// Our passes own all of this state; ImGui or a caller may have changed it.
void resetPassState() {
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_FRAMEBUFFER_SRGB); // the display pass encodes gamma itself
}

} // namespace

PathTracer::PathTracer(const std::filesystem::path& shaderDir) {
    ShaderAssembler assembler(shaderDir);
    AssembledShader vertex = assembler.assemble("fullscreen.vert");
    pathTraceProgram_ = std::make_unique<GlProgram>(vertex, assembler.assemble("pathtrace.frag"));
    displayProgram_ = std::make_unique<GlProgram>(vertex, assembler.assemble("display.frag"));

    const GlProgram& trace = *pathTraceProgram_;
    trace.bindUniformBlock("FrameBlock", kFrameBlockBinding);
    Accumulator::bindSamplers(trace, kAccumulationUnit);
    for (int i = 0; i < GpuScene::kTextureCount; ++i) trace.bindSamplerUnit(GpuScene::kSamplerNames[i], kSceneUnit + i);
    sphereCountLocation_ = trace.uniformLocation("uSphereCount");
    quadCountLocation_ = trace.uniformLocation("uQuadCount");
    diskCountLocation_ = trace.uniformLocation("uDiskCount");
    lightCountLocation_ = trace.uniformLocation("uLightCount");
    environmentLightLocation_ = trace.uniformLocation("uEnvironmentLight");
    environmentMap_.attach(trace, kEnvironmentUnit);

    const GlProgram& show = *displayProgram_;
    show.bindSamplerUnit("uSum", 0);
    show.bindSamplerUnit("uCompensation", 1);
    invSampleCountLocation_ = show.uniformLocation("uInvSampleCount");
    exposureScaleLocation_ = show.uniformLocation("uExposureScale");
    outputSizeLocation_ = show.uniformLocation("uOutputSize");

    emptyVertexArray_ = createVertexArray();
    frameUniformBuffer_ = createBuffer();
    glBindBuffer(GL_UNIFORM_BUFFER, frameUniformBuffer_.id());
    glBufferData(GL_UNIFORM_BUFFER, sizeof(FrameUniforms), nullptr, GL_DYNAMIC_DRAW);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
}

void PathTracer::setScene(const Scene& scene, const EnvironmentMap* environmentMap) {
    std::optional<EnvironmentMap> loaded;
    if (!environmentMap && !scene.environmentMap.empty()) environmentMap = &loaded.emplace(loadEnvironmentMap(scene.environmentMap));
    environmentMap_.upload(scene.environmentMap.empty() ? nullptr : environmentMap, scene.environmentIntensity,
                           scene.environmentRotationDeg);
    gpuScene_.upload(scene, environmentMap_.hasMap() ? std::optional<glm::vec3>(environmentMap_.meanRadiance()) : std::nullopt);
    glUseProgram(pathTraceProgram_->id());
    glUniform1i(sphereCountLocation_, gpuScene_.sphereCount());
    glUniform1i(quadCountLocation_, gpuScene_.quadCount());
    glUniform1i(diskCountLocation_, gpuScene_.diskCount());
    setLightUniforms();
    camera_ = scene.camera;
    environmentRadiance_ = scene.environment;
    restart();
}

void PathTracer::setMaterials(const std::vector<Material>& materials) {
    gpuScene_.uploadMaterials(materials);
    setLightUniforms();
    restart();
}

void PathTracer::setLightUniforms() {
    glUseProgram(pathTraceProgram_->id());
    glUniform1i(lightCountLocation_, gpuScene_.lightCount());
    glUniform1i(environmentLightLocation_, gpuScene_.environmentLight());
}

void PathTracer::setSettings(const RenderSettings& settings) {
    if (settings == settings_) return;
    settings_ = settings;
    restart();
}

void PathTracer::setImageSize(glm::ivec2 size) {
    accumulator_.resize(size);
}

void PathTracer::updateFrameUniforms() {
    glm::ivec2 size = accumulator_.size();
    glm::vec3 forward = glm::normalize(camera_.target - camera_.eye);
    glm::vec3 right = glm::normalize(glm::cross(forward, camera_.up));
    FrameUniforms frame{};
    frame.cameraEye = camera_.eye;
    frame.tanHalfFovY = std::tan(glm::radians(camera_.vfovDeg) * 0.5f);
    frame.cameraRight = right;
    frame.aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
    frame.cameraUp = glm::cross(right, forward);
    frame.frameIndex = static_cast<std::uint32_t>(accumulator_.sampleCount());
    frame.cameraForward = forward;
    frame.seed = settings_.seed;
    frame.environmentRadiance = environmentRadiance_;
    frame.maxDepth = settings_.maxDepth;
    frame.imageSize = size;
    frame.samplerMode = static_cast<std::uint32_t>(settings_.sampler);
    frame.sampleBudget = settings_.sampleBudget;
    frame.integrator = static_cast<std::uint32_t>(settings_.integrator);
    glBindBuffer(GL_UNIFORM_BUFFER, frameUniformBuffer_.id());
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof(FrameUniforms), &frame);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
}

void PathTracer::renderSample() {
    updateFrameUniforms();
    resetPassState();
    accumulator_.beginPass(kAccumulationUnit);
    glUseProgram(pathTraceProgram_->id());
    glBindBufferBase(GL_UNIFORM_BUFFER, kFrameBlockBinding, frameUniformBuffer_.id());
    gpuScene_.bind(kSceneUnit);
    environmentMap_.bind();
    glBindVertexArray(emptyVertexArray_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    accumulator_.endPass();
}

void PathTracer::display(glm::ivec2 viewportSize, float exposureStops) const {
    resetPassState();
    glViewport(0, 0, viewportSize.x, viewportSize.y);
    glUseProgram(displayProgram_->id());
    int samples = accumulator_.sampleCount();
    glUniform1f(invSampleCountLocation_, samples > 0 ? 1.0f / static_cast<float>(samples) : 0.0f);
    glUniform1f(exposureScaleLocation_, std::exp2(exposureStops));
    glUniform2f(outputSizeLocation_, static_cast<float>(viewportSize.x), static_cast<float>(viewportSize.y));
    accumulator_.bindLatest(0, 1);
    glBindVertexArray(emptyVertexArray_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
}

ImageRgbF PathTracer::readMean() const {
    return accumulator_.readStatistics().mean;
}

ImageRgba8 PathTracer::readToneMapped(float exposureStops) const {
    return renderOffscreenRgba8(accumulator_.size(), [&](glm::ivec2 size) { display(size, exposureStops); });
}

} // namespace ptview
