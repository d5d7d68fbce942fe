#include <ptview/probes/ProbePass.h>

#include <ptview/gl/GlObjects.h>

#include <algorithm>
#include <stdexcept>

namespace ptview {
namespace {

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

std::vector<ProbeData> runProbePass(const GlProgram& program, int count, const std::vector<ProbeData>& inputs,
                                    int outputCount) {
    if (count <= 0) throw std::invalid_argument("probe pass: count must be positive");
    if (outputCount < 1 || outputCount > 4) throw std::invalid_argument("probe pass: 1 to 4 outputs");
    const int width = std::min(count, kMaxWidth);
    const int height = (count + width - 1) / width;
    const size_t texels = static_cast<size_t>(width) * static_cast<size_t>(height);

    std::vector<GlTexture> inputTextures;
    for (const ProbeData& input : inputs) {
        ProbeData padded(texels, glm::vec4(0.0f));
        std::copy_n(input.begin(), std::min(input.size(), texels), padded.begin());
        inputTextures.push_back(createProbeTexture(width, height, padded.data()));
    }
    std::vector<GlTexture> outputs;
    GlFramebuffer framebuffer = createFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    std::vector<GLenum> attachments;
    for (int i = 0; i < outputCount; ++i) {
        outputs.push_back(createProbeTexture(width, height, nullptr));
        attachments.push_back(static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + i));
        glFramebufferTexture2D(GL_FRAMEBUFFER, attachments.back(), GL_TEXTURE_2D, outputs.back().id(), 0);
    }
    glDrawBuffers(outputCount, attachments.data());
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("probe pass: cannot render to RGBA32F targets");

    glUseProgram(program.id());
    glUniform1i(program.uniformLocation("uWidth"), width);
    glUniform1i(program.uniformLocation("uCount"), count);
    for (size_t k = 0; k < inputTextures.size(); ++k) {
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + k));
        glBindTexture(GL_TEXTURE_2D, inputTextures[k].id());
    }
    glActiveTexture(GL_TEXTURE0);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_DEPTH_TEST);
    glViewport(0, 0, width, height);
    GlVertexArray vertexArray = createVertexArray();
    glBindVertexArray(vertexArray.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);

    std::vector<ProbeData> results(static_cast<size_t>(outputCount));
    for (int i = 0; i < outputCount; ++i) {
        results[static_cast<size_t>(i)].resize(texels);
        glReadBuffer(attachments[static_cast<size_t>(i)]);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, results[static_cast<size_t>(i)].data());
        results[static_cast<size_t>(i)].resize(static_cast<size_t>(count));
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return results;
}

} // namespace ptview
