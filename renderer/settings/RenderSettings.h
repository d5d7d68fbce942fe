#pragma once
// What a render is asked for, in plain values: the settings a path tracer runs with and the
// rectangle of pixels a pass covers. No OpenGL here, so the viewer model, the scripts and the
// metrics can hold them.

#include <ptview/settings/DebugView.h>
#include <ptview/settings/Integrator.h>
#include <ptview/settings/LightPaths.h>
#include <ptview/settings/SamplerMode.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>

namespace ptview {

struct RenderSettings {
    int maxDepth = 8;       // bounces; 0 shows only what the camera sees directly
    std::uint32_t seed = 0; // decorrelates independent renders of the same scene
    // Sobol' converges fastest and is unbiased (issue 22); random stays one option away, and what
    // needs independent samples (a reference's noise floor, variance-based test tolerances) asks
    // for it by name.
    SamplerMode sampler = SamplerMode::Sobol;
    // The samples per pixel the render is heading for: grid and stratified lay out patterns of
    // n^2 <= sampleBudget samples, so a render of exactly that many is fully stratified.
    std::uint32_t sampleBudget = 1024;
    // The best result is the default (the viewer, `ptview render`, bench); naive is for teaching.
    Integrator integrator = Integrator::Full;
    DebugView debugView = DebugView::Radiance;
    // Firefly control, biased: each contribution one path vertex adds to its pixel (throughput x
    // emission, or x a light sample's estimate) is scaled down so that its largest component is at
    // most this (shaders/integrator.glsl, docs/integrators.md). nullopt: no clamp, unbiased.
    std::optional<float> radianceClamp;
    // The light-path explorer (LightPaths.h): all light, or a part of it; k for exactly / at-most.
    LightPaths lightPaths = LightPaths::All;
    int lightPathBounces = 1;

    bool operator==(const RenderSettings& other) const {
        return integrator == other.integrator && maxDepth == other.maxDepth && seed == other.seed && sampler == other.sampler &&
               sampleBudget == other.sampleBudget && debugView == other.debugView && radianceClamp == other.radianceClamp &&
               lightPaths == other.lightPaths && lightPathBounces == other.lightPathBounces;
    }
    bool operator!=(const RenderSettings& other) const { return !(*this == other); }
};

// A rectangle of framebuffer pixels, origin at the lower left as OpenGL counts.
struct PixelRect {
    glm::ivec2 origin{0, 0};
    glm::ivec2 size{0, 0};
};

} // namespace ptview
