#pragma once
// The display transforms of shaders/tonemap.glsl, and their names on the command line and in the UI.

#include <cstdint>
#include <vector>

namespace ptview {

// Values match the kToneMapper* constants of shaders/tonemap.glsl.
enum class ToneMapper : std::uint32_t { Reinhard = 0, Aces = 1, Clamp = 2 };

struct ToneMapperName {
    ToneMapper toneMapper;
    const char* name;
    const char* label; // for the UI
};

// How the mean radiance becomes a displayed colour: scaled by 2^exposureStops, tone mapped, then
// gamma 2.2.
struct DisplaySettings {
    float exposureStops = 0.0f;
    ToneMapper toneMapper = ToneMapper::Reinhard;
    bool highlightNonFinite = false; // show pixels whose mean is NaN or infinite in magenta
};

inline const std::vector<ToneMapperName>& toneMapperNames() {
    static const std::vector<ToneMapperName> names = {
        {ToneMapper::Reinhard, "reinhard", "Reinhard (x / (1 + x))"},
        {ToneMapper::Aces, "aces", "ACES filmic (Narkowicz fit)"},
        {ToneMapper::Clamp, "clamp", "None (clamp to 1)"},
    };
    return names;
}

inline const char* toneMapperName(ToneMapper toneMapper) {
    for (const ToneMapperName& entry : toneMapperNames())
        if (entry.toneMapper == toneMapper) return entry.name;
    return "?";
}

} // namespace ptview
