#pragma once
// The sample generators of shaders/sampler.glsl, and their names on the command line and in the UI.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ptview {

// Values match the kSampler* constants of shaders/sampler.glsl.
enum class SamplerMode : std::uint32_t { Random = 0, Grid = 1, Stratified = 2, Sobol = 3 };

struct SamplerModeName {
    SamplerMode mode;
    const char* name;
};

inline const std::vector<SamplerModeName>& samplerModeNames() {
    static const std::vector<SamplerModeName> names = {
        {SamplerMode::Random, "random"},
        {SamplerMode::Grid, "grid"},
        {SamplerMode::Stratified, "stratified"},
        {SamplerMode::Sobol, "sobol"},
    };
    return names;
}

inline const char* samplerModeName(SamplerMode mode) {
    for (const SamplerModeName& entry : samplerModeNames())
        if (entry.mode == mode) return entry.name;
    return "?";
}

inline std::optional<SamplerMode> parseSamplerMode(const std::string& name) {
    for (const SamplerModeName& entry : samplerModeNames())
        if (name == entry.name) return entry.mode;
    return std::nullopt;
}

} // namespace ptview
