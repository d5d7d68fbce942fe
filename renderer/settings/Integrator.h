#pragma once
// The integrators of shaders/integrator.glsl, and their names on the command line and in the UI.

#include <ptview/settings/EnumTable.h>

#include <cstdint>

namespace ptview {

enum class Integrator : std::uint32_t { Naive = 0, Direct = 1, Mis = 2, Full = 3 };

inline const EnumTable<Integrator>& integratorNames() {
    static const EnumTable<Integrator> table = {
        {Integrator::Naive, "naive", "Naive (BSDF sampling)", "", "kIntegratorNaive"},
        {Integrator::Direct, "direct", "Direct (light sampling)", "", "kIntegratorDirect"},
        {Integrator::Mis, "mis", "DirectMIS (light + BSDF, MIS)", "", "kIntegratorMis"},
        {Integrator::Full, "full", "Full (global illumination)", "", "kIntegratorFull"},
    };
    return table;
}

inline const char* integratorName(Integrator integrator) { return integratorNames().name(integrator); }

} // namespace ptview
