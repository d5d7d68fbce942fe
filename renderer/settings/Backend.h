#pragma once
// How the path tracer runs its GLSL: a full-screen triangle through the fragment stage (OpenGL 4.1,
// everywhere), or a compute dispatch (OpenGL 4.3), which on data-centre GPUs uses every shader core
// rather than the few that feed the graphics pipeline. Same includes, one entry point each.

#include <ptview/settings/EnumTable.h>

#include <cstdint>

namespace ptview {

enum class Backend : std::uint32_t { Fragment = 0, Compute = 1 };

inline const EnumTable<Backend>& backendNames() {
    static const EnumTable<Backend> table = {{Backend::Fragment, "fragment"}, {Backend::Compute, "compute"}};
    return table;
}

inline const char* backendName(Backend backend) { return backendNames().name(backend); }

} // namespace ptview
