#include "WarpProbe.h"

#include "GlObjects.h"

#include <algorithm>
#include <stdexcept>

namespace ptview {
namespace {

constexpr int kProbeWarp = 0;
constexpr int kProbePdf = 1;
constexpr int kMaxWidth = 1024;

GlTexture createProbeTexture(int width, int height, const void* data) {
    GlTexture texture = createTexture();
    glBindTexture(GL_TEXTURE_2D, texture.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, data);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return texture;
}

} // namespace

WarpProbe::WarpProbe(const std::filesystem::path& shaderDir) {
    ShaderAssembler assembler(shaderDir);
    program_ = std::make_unique<GlProgram>(assembler.assemble("fullscreen.vert"), assembler.assemble("warp_probe.frag"));
    program_->bindSamplerUnit("uPoints", 0);
}

void WarpProbe::run(const WarpRequest& request, int mode, int count, const std::vector<glm::vec3>* points,
                    std::vector<glm::vec4>& pointAndPdf, std::vector<glm::vec4>& uAndInverse) const {
    if (count <= 0) throw std::invalid_argument("warp probe: count must be positive");
    const int width = std::min(count, kMaxWidth);
    const int height = (count + width - 1) / width;
    const size_t texels = static_cast<size_t>(width) * static_cast<size_t>(height);

    std::vector<glm::vec4> input(texels, glm::vec4(0.0f));
    if (points)
        for (size_t i = 0; i < points->size(); ++i) input[i] = glm::vec4((*points)[i], 0.0f);
    GlTexture inputTexture = createProbeTexture(width, height, input.data());
    GlTexture outputs[2] = {createProbeTexture(width, height, nullptr), createProbeTexture(width, height, nullptr)};
    GlFramebuffer framebuffer = createFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    const GLenum attachments[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    for (int i = 0; i < 2; ++i)
        glFramebufferTexture2D(GL_FRAMEBUFFER, attachments[i], GL_TEXTURE_2D, outputs[i].id(), 0);
    glDrawBuffers(2, attachments);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("warp probe: cannot render to RGBA32F targets");

    const GLuint id = program_->id();
    glUseProgram(id);
    std::uint32_t samplesPerPixel = request.samplesPerPixel ? request.samplesPerPixel : static_cast<std::uint32_t>(count);
    glUniform1i(glGetUniformLocation(id, "uProbeMode"), mode);
    glUniform1i(glGetUniformLocation(id, "uWarp"), static_cast<int>(request.warp));
    glUniform1f(glGetUniformLocation(id, "uCosThetaMax"), request.cosThetaMax);
    glUniform1i(glGetUniformLocation(id, "uWidth"), width);
    glUniform1i(glGetUniformLocation(id, "uCount"), count);
    glUniform1ui(glGetUniformLocation(id, "uSamplerMode"), static_cast<GLuint>(request.sampler));
    glUniform1ui(glGetUniformLocation(id, "uSampleBudget"), request.sampleBudget ? request.sampleBudget : samplesPerPixel);
    glUniform1ui(glGetUniformLocation(id, "uSamplesPerPixel"), samplesPerPixel);
    glUniform1ui(glGetUniformLocation(id, "uSeed"), request.seed);
    glUniform1ui(glGetUniformLocation(id, "uDimension"), request.dimension);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, inputTexture.id());

    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_DEPTH_TEST);
    glViewport(0, 0, width, height);
    GlVertexArray vertexArray = createVertexArray();
    glBindVertexArray(vertexArray.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);

    std::vector<glm::vec4>* results[2] = {&pointAndPdf, &uAndInverse};
    for (int i = 0; i < 2; ++i) {
        results[i]->resize(texels);
        glReadBuffer(attachments[i]);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, results[i]->data());
        results[i]->resize(static_cast<size_t>(count));
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::vector<WarpSample> WarpProbe::sample(const WarpRequest& request) const {
    std::vector<glm::vec4> pointAndPdf, uAndInverse;
    run(request, kProbeWarp, request.count, nullptr, pointAndPdf, uAndInverse);
    std::vector<WarpSample> samples(static_cast<size_t>(request.count));
    for (size_t i = 0; i < samples.size(); ++i) {
        samples[i].point = glm::vec3(pointAndPdf[i]);
        samples[i].pdf = pointAndPdf[i].w;
        samples[i].u = glm::vec2(uAndInverse[i]);
        samples[i].inverse = glm::vec2(uAndInverse[i].z, uAndInverse[i].w);
    }
    return samples;
}

std::vector<float> WarpProbe::pdf(const WarpRequest& request, const std::vector<glm::vec3>& points) const {
    std::vector<glm::vec4> pointAndPdf, unused;
    run(request, kProbePdf, static_cast<int>(points.size()), &points, pointAndPdf, unused);
    std::vector<float> densities(points.size());
    for (size_t i = 0; i < points.size(); ++i) densities[i] = pointAndPdf[i].x;
    return densities;
}

} // namespace ptview
