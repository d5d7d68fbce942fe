#pragma once
// How GoogleTest prints the render settings' enums (a parameter, a tuple of them, a failed
// check): by the names the CLI and the scripts use, where it would print the bytes of an int.

#include <ptview/settings/Integrator.h>
#include <ptview/settings/SamplerMode.h>

#include <ostream>

namespace ptview {

inline void PrintTo(Integrator integrator, std::ostream* out) { *out << integratorName(integrator); }
inline void PrintTo(SamplerMode mode, std::ostream* out) { *out << samplerModeName(mode); }

} // namespace ptview
