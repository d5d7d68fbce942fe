#pragma once
// The integrators of shaders/integrator.glsl, and their names on the command line and in the UI.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ptview {

// Values match the kIntegrator* constants of shaders/integrator.glsl.
enum class Integrator : std::uint32_t { Naive = 0, Direct = 1, Mis = 2, Full = 3 };

struct IntegratorName {
    Integrator integrator;
    const char* name;
    const char* label; // for the UI
};

inline const std::vector<IntegratorName>& integratorNames() {
    static const std::vector<IntegratorName> names = {
        {Integrator::Naive, "naive", "Naive (BSDF sampling)"},
        {Integrator::Direct, "direct", "Direct (light sampling)"},
        {Integrator::Mis, "mis", "DirectMIS (light + BSDF, MIS)"},
        {Integrator::Full, "full", "Full (global illumination)"},
    };
    return names;
}

inline const char* integratorName(Integrator integrator) {
    for (const IntegratorName& entry : integratorNames())
        if (entry.integrator == integrator) return entry.name;
    return "?";
}

} // namespace ptview
