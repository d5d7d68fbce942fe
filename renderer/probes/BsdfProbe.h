#pragma once
// Runs the real GLSL BSDFs headless (shaders/bsdf_probe.frag) and reads back samples and values:
// the harness of the BSDF tests. Needs a current context.

#include <ptview/gl/GlProgram.h>
#include <ptview/settings/SamplerMode.h>
#include <ptview/scene/Scene.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

namespace ptview {

struct BsdfProbeSample {
    glm::vec3 wiLocal;
    float pdfSolidAngle = 0.0f; // of the sampling strategy; for a delta lobe, its probability
    glm::vec3 weight;           // f |cos| / pdf
    bool isDelta = false;
    glm::vec3 fAtWi;            // bsdfF(wo, wi) re-evaluated at the sampled wi
    float pdfAtWi = 0.0f;       // bsdfPdf(wo, wi) re-evaluated at the sampled wi
};

struct BsdfProbeValue {
    glm::vec3 f;
    float pdfSolidAngle = 0.0f;
};

class BsdfProbe {
public:
    explicit BsdfProbe(const std::filesystem::path& shaderDir = PTVIEW_SHADER_DIR);

    // count samples; item i uses woLocal[i % woLocal.size()] and sample i of the sampler.
    std::vector<BsdfProbeSample> sample(const Material& material, const std::vector<glm::vec3>& woLocal, int count,
                                        std::uint32_t seed = 0, SamplerMode sampler = SamplerMode::Random) const;
    // f and pdf for each (woLocal[i], wiLocal[i]) pair.
    std::vector<BsdfProbeValue> evaluate(const Material& material, const std::vector<glm::vec3>& woLocal,
                                         const std::vector<glm::vec3>& wiLocal) const;

private:
    void setMaterial(const Material& material) const;
    std::unique_ptr<GlProgram> program_;
};

} // namespace ptview
