#pragma once
// The sample generators of shaders/sampler.glsl, and their names on the command line and in the UI.

#include <ptview/settings/EnumTable.h>

#include <cstdint>
#include <optional>
#include <string>

namespace ptview {

enum class SamplerMode : std::uint32_t { Random = 0, Grid = 1, Stratified = 2, Sobol = 3 };

// Grid and stratified lay their patterns out for a sample budget (RenderSettings::sampleBudget):
// stopped short of it, an image holds part of a pattern, which shows as coloured patches (grid)
// or a biased estimate. So a viewer that picks one of them without a target sets this one
// (16 x 16 cells), where the pattern is complete.
constexpr int kPatternTargetSamples = 256;

// Grid and stratified: meant to be stopped at a complete pattern (kPatternTargetSamples).
inline bool needsPatternTarget(SamplerMode mode) { return mode == SamplerMode::Grid || mode == SamplerMode::Stratified; }

// The descriptions are for the UI's tooltip and --help: what a mode is, and whether it is biased.
inline const EnumTable<SamplerMode>& samplerModeNames() {
    static const EnumTable<SamplerMode> table = {
        {SamplerMode::Random, "random", nullptr, "independent random numbers: unbiased at any sample count",
         "kSamplerRandom"},
        {SamplerMode::Grid, "grid", nullptr,
         "cell centres of an n x n grid: regular and biased by design (aliasing), for teaching; "
         "a full grid only at the target spp",
         "kSamplerGrid"},
        {SamplerMode::Stratified, "stratified", nullptr,
         "one jittered point per grid cell: less noise at the target spp, where the pattern is complete; "
         "before it the partial pattern can show as patches",
         "kSamplerStratified"},
        {SamplerMode::Sobol, "sobol", nullptr,
         "scrambled Sobol' sequence: unbiased, least noise, best at powers of two spp", "kSamplerSobol"},
    };
    return table;
}

inline const char* samplerModeName(SamplerMode mode) { return samplerModeNames().name(mode); }
inline std::optional<SamplerMode> parseSamplerMode(const std::string& name) { return samplerModeNames().parse(name); }

} // namespace ptview
