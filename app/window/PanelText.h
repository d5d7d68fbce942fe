#pragma once
// Words the panels show that depend on numbers and state, as plain functions (no ImGui), so a
// test can read what the window would say.

#include <ptview/settings/Integrator.h>
#include <ptview/settings/SamplerMode.h>

#include <string>

namespace ptview {

// "1 program", "2 programs": the count with its noun, singular for one.
inline std::string countOf(int count, const std::string& noun) {
    return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

// The heading of a view's statistics: which side it is only when there are two ("left: full,
// sobol"), else just the integrator and sampler.
inline std::string viewHeading(bool comparing, bool leftSide, Integrator integrator, SamplerMode sampler) {
    std::string heading = std::string(integratorName(integrator)) + ", " + samplerModeName(sampler);
    return comparing ? std::string(leftSide ? "left: " : "right: ") + heading : heading;
}

} // namespace ptview
