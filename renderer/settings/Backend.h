#pragma once
// How the path tracer runs its GLSL: a full-screen triangle through the fragment stage (OpenGL 4.1,
// everywhere), or a compute dispatch (OpenGL 4.3), which on data-centre GPUs uses every shader core
// rather than the few that feed the graphics pipeline. Same includes, one entry point each.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ptview {

enum class Backend : std::uint32_t { Fragment = 0, Compute = 1 };

struct BackendName {
    Backend backend;
    const char* name;
};

inline const std::vector<BackendName>& backendNames() {
    static const std::vector<BackendName> names = {{Backend::Fragment, "fragment"}, {Backend::Compute, "compute"}};
    return names;
}

inline const char* backendName(Backend backend) {
    return backend == Backend::Compute ? "compute" : "fragment";
}

} // namespace ptview
