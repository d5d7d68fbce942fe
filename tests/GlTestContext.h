#pragma once
// One headless OpenGL context per test process, created on first use.
#include <ptview/gl/HeadlessContext.h>
#include <ptview/tracer/PathTracer.h>

#include <cstdint>

namespace ptview::testing {

inline HeadlessContext& glContext() {
    static HeadlessContext context;
    return context;
}

// Naive path tracing at this depth and seed: what RenderSettings{depth, seed} gave the tests
// written before the default integrator became full, spelt out so that they test what they did.
inline RenderSettings naiveSettings(int maxDepth, std::uint32_t seed) {
    RenderSettings settings;
    settings.maxDepth = maxDepth;
    settings.seed = seed;
    settings.integrator = Integrator::Naive;
    settings.sampler = SamplerMode::Random;
    return settings;
}

} // namespace ptview::testing
