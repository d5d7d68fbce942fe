#pragma once
// Runs the real GLSL sampler and warps headless and reads back what they produce: the harness of
// the statistical tests and the source of the warp visualizer's points. Needs a current context.

#include <ptview/gl/GlProgram.h>
#include <ptview/probes/ProbePass.h>
#include <ptview/settings/SamplerMode.h>
#include <ptview/geometry/Warp.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace ptview {

struct WarpRequest {
    Warp warp = Warp::Square;
    SamplerMode sampler = SamplerMode::Random;
    int count = 1024;                 // total samples
    std::uint32_t samplesPerPixel = 0; // samples per simulated pixel; 0: all in one pixel
    std::uint32_t sampleBudget = 0;    // grid/stratified pattern size; 0: samplesPerPixel
    std::uint32_t seed = 0;
    std::uint32_t dimension = 0;       // which sampler dimension feeds the warp
    float cosThetaMax = 0.5f;          // uniform cone only (0.5: a 60 degree half-angle)
    float g = 0.5f;                    // henyey-greenstein only: the mean cosine, in (-1, 1)
};

struct WarpSample {
    glm::vec2 u;        // what the sampler produced
    glm::vec3 point;    // warp(u); 2D domains have z = 0
    float pdf = 0.0f;   // the warp's density at point
    glm::vec2 inverse;  // inverse(warp(u)); equals u where the inverse is exact
};

// The text of "warp_ids.glsl": uWarp's values, kWarpSquare ... (Warp, renderer/geometry/Warp.h).
std::string warpIdsGlsl();

class WarpProbe {
public:
    explicit WarpProbe(const std::filesystem::path& shaderDir = PTVIEW_SHADER_DIR);

    // Sample i is sample i % samplesPerPixel of pixel i / samplesPerPixel.
    std::vector<WarpSample> sample(const WarpRequest& request) const;
    // The density of request.warp at each point (request.warp, cosThetaMax and g are used).
    std::vector<float> pdf(const WarpRequest& request, const std::vector<glm::vec3>& points) const;

private:
    std::vector<ProbeData> run(const WarpRequest& request, int mode, int count, const ProbeData& points) const;

    std::unique_ptr<GlProgram> program_;
};

} // namespace ptview
