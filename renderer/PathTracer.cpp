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
constexpr int kSceneUnit = kAccumulationUnit + Accumulator::kTextureCount; // units 3..11
constexpr int kEnvironmentUnit = kSceneUnit + GpuScene::kTextureCount;     // units 12..14
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

PathTracer::Programs PathTracer::buildPrograms() const {
    ShaderAssembler assembler(shaderDir_);
    AssembledShader vertex = assembler.assemble("fullscreen.vert");
    Programs programs;
    programs.pathTrace = std::make_unique<GlProgram>(vertex, assembler.assemble("pathtrace.frag"));
    programs.display = std::make_unique<GlProgram>(vertex, assembler.assemble("display.frag"));

    const GlProgram& trace = *programs.pathTrace;
    trace.bindUniformBlock("FrameBlock", kFrameBlockBinding);
    Accumulator::bindSamplers(trace, kAccumulationUnit);

    const GlProgram& show = *programs.display;
    show.bindSamplerUnit("uSum", 0);
    show.bindSamplerUnit("uCompensation", 1);
    programs.invSampleCount = show.uniformLocation("uInvSampleCount");
    programs.exposureScale = show.uniformLocation("uExposureScale");
    programs.toneMapper = show.uniformLocation("uToneMapper");
    programs.outputOrigin = show.uniformLocation("uOutputOrigin");
    programs.outputSize = show.uniformLocation("uOutputSize");
    return programs;
}

PathTracer::PathTracer(const std::filesystem::path& shaderDir) : shaderDir_(shaderDir) {
    programs_ = buildPrograms();
    gpuScene_.attach(*programs_.pathTrace, kSceneUnit);
    environmentMap_.attach(*programs_.pathTrace, kEnvironmentUnit);
    emptyVertexArray_ = createVertexArray();
    frameUniformBuffer_ = createBuffer();
    glBindBuffer(GL_UNIFORM_BUFFER, frameUniformBuffer_.id());
    glBufferData(GL_UNIFORM_BUFFER, sizeof(FrameUniforms), nullptr, GL_DYNAMIC_DRAW);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
}

void PathTracer::reloadShaders() {
    Programs rebuilt = buildPrograms(); // throws before anything is replaced
    programs_ = std::move(rebuilt);
    gpuScene_.attach(*programs_.pathTrace, kSceneUnit);
    environmentMap_.attach(*programs_.pathTrace, kEnvironmentUnit);
    restart();
}

void PathTracer::setScene(const Scene& scene, const EnvironmentMap* environmentMap) {
    std::optional<EnvironmentMap> loaded;
    if (!environmentMap && !scene.environmentMap.empty()) environmentMap = &loaded.emplace(loadEnvironmentMap(scene.environmentMap));
    environmentMap_.upload(scene.environmentMap.empty() ? nullptr : environmentMap, scene.environmentIntensity,
                           scene.environmentRotationDeg);
    gpuScene_.upload(scene, environmentMap_.hasMap() ? std::optional<glm::vec3>(environmentMap_.meanRadiance()) : std::nullopt);
    camera_ = scene.camera;
    environmentRadiance_ = scene.environment;
    restart();
}

void PathTracer::setMaterials(const std::vector<Material>& materials) {
    gpuScene_.uploadMaterials(materials);
    restart();
}

void PathTracer::setCamera(const CameraDesc& camera) {
    glm::ivec2 resolution = camera_.resolution;
    camera_ = camera;
    camera_.resolution = resolution;
    restart();
}

void PathTracer::restart() {
    accumulator_.restart();
    nextRow_ = 0;
    ++restartCount_;
}

void PathTracer::setSettings(const RenderSettings& settings) {
    if (settings == settings_) return;
    settings_ = settings;
    restart();
}

void PathTracer::setImageSize(glm::ivec2 size) {
    if (size == accumulator_.size()) return;
    accumulator_.resize(size);
    nextRow_ = 0;
    ++restartCount_;
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
    renderRows(accumulator_.size().y);
}

bool PathTracer::renderRows(int rowCount) {
    glm::ivec2 size = accumulator_.size();
    int endRow = std::min(size.y, nextRow_ + std::max(1, rowCount));
    updateFrameUniforms();
    resetPassState();
    accumulator_.beginPass(kAccumulationUnit);
    if (nextRow_ > 0 || endRow < size.y) { // the rest of the target keeps what earlier tiles wrote
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, nextRow_, size.x, endRow - nextRow_);
    }
    glUseProgram(programs_.pathTrace->id());
    glBindBufferBase(GL_UNIFORM_BUFFER, kFrameBlockBinding, frameUniformBuffer_.id());
    gpuScene_.bind();
    environmentMap_.bind();
    glBindVertexArray(emptyVertexArray_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDisable(GL_SCISSOR_TEST);
    if (endRow < size.y) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        nextRow_ = endRow;
        return false;
    }
    accumulator_.endPass();
    nextRow_ = 0;
    return true;
}

void PathTracer::display(PixelRect target, const DisplaySettings& settings, PixelRect clip) const {
    resetPassState();
    glViewport(target.origin.x, target.origin.y, target.size.x, target.size.y);
    glEnable(GL_SCISSOR_TEST);
    glScissor(clip.origin.x, clip.origin.y, clip.size.x, clip.size.y);
    glUseProgram(programs_.display->id());
    int samples = accumulator_.displayedSampleCount();
    glUniform1f(programs_.invSampleCount, samples > 0 ? 1.0f / static_cast<float>(samples) : 0.0f);
    glUniform1f(programs_.exposureScale, std::exp2(settings.exposureStops));
    glUniform1ui(programs_.toneMapper, static_cast<GLuint>(settings.toneMapper));
    glUniform2f(programs_.outputOrigin, static_cast<float>(target.origin.x), static_cast<float>(target.origin.y));
    glUniform2f(programs_.outputSize, static_cast<float>(target.size.x), static_cast<float>(target.size.y));
    accumulator_.bindLatest(0, 1);
    glBindVertexArray(emptyVertexArray_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDisable(GL_SCISSOR_TEST);
}

ImageRgbF PathTracer::readMean() const {
    return accumulator_.readStatistics().mean;
}

ImageRgba8 PathTracer::readToneMapped(const DisplaySettings& settings) const {
    return renderOffscreenRgba8(accumulator_.size(), [&](glm::ivec2 size) { display(PixelRect{{0, 0}, size}, settings); });
}

} // namespace ptview
