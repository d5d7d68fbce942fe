#pragma once
// The display transforms of shaders/tonemap.glsl, and their names on the command line and in the UI.

#include <ptview/settings/DisplayView.h>
#include <ptview/settings/EnumTable.h>

#include <cstdint>

namespace ptview {

enum class ToneMapper : std::uint32_t { Reinhard = 0, Aces = 1, Clamp = 2 };

// How the mean radiance becomes a displayed colour: scaled by 2^exposureStops, tone mapped, then
// gamma 2.2.
struct DisplaySettings {
    float exposureStops = 0.0f;
    ToneMapper toneMapper = ToneMapper::Reinhard;
    bool highlightNonFinite = false; // show pixels whose mean is NaN or infinite in magenta
    bool denoised = false;           // show the denoised image where there is one (PathTracer::hasDenoised)
    // The image, or its error or difference (DisplayView.h) against PathTracer::setOtherImage's
    // image; the estimated error is always of the raw samples, denoised or not.
    DisplayView view = DisplayView::Image;
    ErrorMapRange mapRange;
};

inline const EnumTable<ToneMapper>& toneMapperNames() {
    static const EnumTable<ToneMapper> table = {
        {ToneMapper::Reinhard, "reinhard", "Reinhard (x / (1 + x))", "", "kToneMapperReinhard"},
        {ToneMapper::Aces, "aces", "ACES filmic (Narkowicz fit)", "", "kToneMapperAces"},
        {ToneMapper::Clamp, "clamp", "None (clamp to 1)", "", "kToneMapperClamp"},
    };
    return table;
}

inline const char* toneMapperName(ToneMapper toneMapper) { return toneMapperNames().name(toneMapper); }

} // namespace ptview
