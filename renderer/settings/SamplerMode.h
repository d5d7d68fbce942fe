#pragma once
// The sample generators of shaders/sampler.glsl, and their names on the command line and in the UI.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ptview {

// Values match the kSampler* constants of shaders/sampler.glsl.
enum class SamplerMode : std::uint32_t { Random = 0, Grid = 1, Stratified = 2, Sobol = 3 };

// Grid and stratified lay their patterns out for a sample budget (RenderSettings::sampleBudget):
// stopped short of it, an image holds part of a pattern, which shows as coloured patches (grid)
// or a biased estimate. So a viewer that picks one of them without a target sets this one
// (16 x 16 cells), where the pattern is complete.
constexpr int kPatternTargetSamples = 256;

struct SamplerModeName {
    SamplerMode mode;
    const char* name;
    const char* description; // for the UI's tooltip and --help: what it is, and whether it is biased
    bool needsTarget;        // meant to be stopped at a complete pattern (kPatternTargetSamples)
};

inline const std::vector<SamplerModeName>& samplerModeNames() {
    static const std::vector<SamplerModeName> names = {
        {SamplerMode::Random, "random", "independent random numbers: unbiased at any sample count", false},
        {SamplerMode::Grid, "grid",
         "cell centres of an n x n grid: regular and biased by design (aliasing), for teaching; "
         "a full grid only at the target spp",
         true},
        {SamplerMode::Stratified, "stratified",
         "one jittered point per grid cell: less noise at the target spp, where the pattern is complete; "
         "before it the partial pattern can show as patches",
         true},
        {SamplerMode::Sobol, "sobol", "scrambled Sobol' sequence: unbiased, least noise, best at powers of two spp", false},
    };
    return names;
}

inline const SamplerModeName& samplerModeInfo(SamplerMode mode) {
    for (const SamplerModeName& entry : samplerModeNames())
        if (entry.mode == mode) return entry;
    return samplerModeNames().front();
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
