#include "WarpProbe.h"

#include "GlslEnums.h"
#include "ProbePass.h"

namespace ptview {
namespace {

constexpr int kProbeWarp = 0;
constexpr int kProbePdf = 1;

} // namespace

WarpProbe::WarpProbe(const std::filesystem::path& shaderDir) {
    ShaderAssembler assembler(shaderDir);
    addGlslEnums(assembler); // the sample generators
    program_ = std::make_unique<GlProgram>(assembler.assemble("fullscreen.vert"), assembler.assemble("warp_probe.frag"));
    program_->bindSamplerUnit("uPoints", 0);
}

std::vector<ProbeData> WarpProbe::run(const WarpRequest& request, int mode, int count, const ProbeData& points) const {
    const GLuint id = program_->id();
    glUseProgram(id);
    std::uint32_t samplesPerPixel = request.samplesPerPixel ? request.samplesPerPixel : static_cast<std::uint32_t>(count);
    glUniform1i(program_->uniformLocation("uProbeMode"), mode);
    glUniform1i(program_->uniformLocation("uWarp"), static_cast<int>(request.warp));
    glUniform1f(program_->uniformLocation("uCosThetaMax"), request.cosThetaMax);
    glUniform1ui(program_->uniformLocation("uSamplerMode"), static_cast<GLuint>(request.sampler));
    glUniform1ui(program_->uniformLocation("uSampleBudget"), request.sampleBudget ? request.sampleBudget : samplesPerPixel);
    glUniform1ui(program_->uniformLocation("uSamplesPerPixel"), samplesPerPixel);
    glUniform1ui(program_->uniformLocation("uSeed"), request.seed);
    glUniform1ui(program_->uniformLocation("uDimension"), request.dimension);
    return runProbePass(*program_, count, {points}, 2);
}

std::vector<WarpSample> WarpProbe::sample(const WarpRequest& request) const {
    std::vector<ProbeData> outputs = run(request, kProbeWarp, request.count, {});
    const ProbeData& pointAndPdf = outputs[0];
    const ProbeData& uAndInverse = outputs[1];
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
    ProbeData input;
    input.reserve(points.size());
    for (const glm::vec3& point : points) input.emplace_back(point, 0.0f);
    std::vector<ProbeData> outputs = run(request, kProbePdf, static_cast<int>(points.size()), input);
    std::vector<float> densities(points.size());
    for (size_t i = 0; i < points.size(); ++i) densities[i] = outputs[0][i].x;
    return densities;
}

} // namespace ptview
