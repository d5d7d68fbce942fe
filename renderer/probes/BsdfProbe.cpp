#include <ptview/probes/BsdfProbe.h>

#include <ptview/gpu/ShaderFeatures.h>

#include <ptview/probes/ProbePass.h>

#include <stdexcept>

namespace ptview {
namespace {

constexpr int kProbeSample = 0;
constexpr int kProbeEvaluate = 1;

ProbeData directionsCycled(const std::vector<glm::vec3>& directions, size_t count) {
    if (directions.empty()) throw std::invalid_argument("BSDF probe: no directions");
    ProbeData data(count);
    for (size_t i = 0; i < count; ++i) data[i] = glm::vec4(directions[i % directions.size()], 0.0f);
    return data;
}

} // namespace

BsdfProbe::BsdfProbe(const std::filesystem::path& shaderDir) {
    ShaderAssembler assembler(shaderDir);
    specializeBsdfs(assembler, ShaderFeatures::all());
    program_ = std::make_unique<GlProgram>(assembler.assemble("fullscreen.vert"), assembler.assemble("bsdf_probe.frag"));
    program_->bindSamplerUnit("uWo", 0);
    program_->bindSamplerUnit("uWi", 1);
}

void BsdfProbe::setMaterial(const Material& material) const {
    glUseProgram(program_->id());
    glUniform1ui(program_->uniformLocation("uMaterialType"), static_cast<GLuint>(material.type));
    glUniform3f(program_->uniformLocation("uColor"), material.color.r, material.color.g, material.color.b);
    glUniform1f(program_->uniformLocation("uIor"), material.ior);
    glUniform1f(program_->uniformLocation("uRoughness"), material.roughness);
    glUniform1f(program_->uniformLocation("uMetallic"), material.metallic);
    glUniform1f(program_->uniformLocation("uTransmission"), material.transmission);
}

std::vector<BsdfProbeSample> BsdfProbe::sample(const Material& material, const std::vector<glm::vec3>& woLocal,
                                               int count, std::uint32_t seed, SamplerMode sampler) const {
    setMaterial(material);
    glUniform1i(program_->uniformLocation("uProbeMode"), kProbeSample);
    glUniform1ui(program_->uniformLocation("uSamplerMode"), static_cast<GLuint>(sampler));
    glUniform1ui(program_->uniformLocation("uSeed"), seed);
    std::vector<ProbeData> out =
        runProbePass(*program_, count, {directionsCycled(woLocal, static_cast<size_t>(count))}, 3);
    std::vector<BsdfProbeSample> samples(static_cast<size_t>(count));
    for (size_t i = 0; i < samples.size(); ++i) {
        samples[i].wiLocal = glm::vec3(out[0][i]);
        samples[i].pdfSolidAngle = out[0][i].w;
        samples[i].weight = glm::vec3(out[1][i]);
        samples[i].isDelta = out[1][i].w > 0.5f;
        samples[i].fAtWi = glm::vec3(out[2][i]);
        samples[i].pdfAtWi = out[2][i].w;
    }
    return samples;
}

std::vector<BsdfProbeValue> BsdfProbe::evaluate(const Material& material, const std::vector<glm::vec3>& woLocal,
                                                const std::vector<glm::vec3>& wiLocal) const {
    if (woLocal.size() != wiLocal.size()) throw std::invalid_argument("BSDF probe: wo and wi counts differ");
    setMaterial(material);
    glUniform1i(program_->uniformLocation("uProbeMode"), kProbeEvaluate);
    std::vector<ProbeData> out = runProbePass(*program_, static_cast<int>(woLocal.size()),
                                              {directionsCycled(woLocal, woLocal.size()),
                                               directionsCycled(wiLocal, wiLocal.size())}, 1);
    std::vector<BsdfProbeValue> values(woLocal.size());
    for (size_t i = 0; i < values.size(); ++i) values[i] = {glm::vec3(out[0][i]), out[0][i].w};
    return values;
}

} // namespace ptview
