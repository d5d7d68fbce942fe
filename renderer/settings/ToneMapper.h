#pragma once
// The display transforms of shaders/tonemap.glsl, and their names on the command line and in the UI.

#include <ptview/settings/DisplayView.h>
#include <ptview/settings/EnumTable.h>

#include <cstdint>

namespace ptview {

// Ocio: the OpenColorIO display/view loaded with --ocio-config (PathTracer::setOcioView); it
// replaces the tone mapper and the display transfer both.
enum class ToneMapper : std::uint32_t { Reinhard = 0, Aces = 1, Clamp = 2, Agx = 3, Ocio = 4 };

// How display-linear values in [0, 1] become the code values a display expects (shaders/srgb.glsl).
// Gamma 2.2 is what ptview used before the exact sRGB curve: provenance written then has no
// "display_transfer" and is read as gamma 2.2, so that `render --from` reproduces those files.
enum class DisplayTransfer : std::uint32_t { Srgb = 0, Gamma22 = 1 };

// How the mean radiance becomes a displayed colour: scaled by 2^exposureStops, tone mapped, then
// encoded with `transfer`.
struct DisplaySettings {
    float exposureStops = 0.0f;
    ToneMapper toneMapper = ToneMapper::Reinhard;
    bool highlightNonFinite = false; // show pixels whose mean is NaN or infinite in magenta
    bool denoised = false;           // show the denoised image where there is one (PathTracer::hasDenoised)
    // The image, or its error or difference (DisplayView.h) against PathTracer::setOtherImage's
    // image; the estimated error is always of the raw samples, denoised or not.
    DisplayView view = DisplayView::Image;
    ErrorMapRange mapRange{};
    DisplayTransfer transfer = DisplayTransfer::Srgb;
};

inline const EnumTable<ToneMapper>& toneMapperNames() {
    static const EnumTable<ToneMapper> table = {
        {ToneMapper::Reinhard, "reinhard", "Reinhard (x / (1 + x))", "", "kToneMapperReinhard"},
        {ToneMapper::Aces, "aces", "ACES filmic (Narkowicz fit)", "", "kToneMapperAces"},
        {ToneMapper::Clamp, "clamp", "None (clamp to 1)", "", "kToneMapperClamp"},
        {ToneMapper::Agx, "agx", "AgX (Blender 4 style)",
         "Troy Sobotka's AgX: log2 encoding of 16.5 stops around 0.18 and a sigmoid; highlights desaturate to white",
         "kToneMapperAgx"},
        {ToneMapper::Ocio, "ocio", "OpenColorIO view",
         "the display and view of an OpenColorIO config (--ocio-config, --ocio-display, --ocio-view)", "kToneMapperOcio"},
    };
    return table;
}

inline const char* toneMapperName(ToneMapper toneMapper) { return toneMapperNames().name(toneMapper); }

inline const EnumTable<DisplayTransfer>& displayTransferNames() {
    static const EnumTable<DisplayTransfer> table = {
        {DisplayTransfer::Srgb, "srgb", "sRGB (IEC 61966-2-1)", "the exact piecewise sRGB curve", "kDisplayTransferSrgb"},
        {DisplayTransfer::Gamma22, "gamma-2.2", "Gamma 2.2",
         "a pure power 1/2.2, as ptview wrote images before it used the sRGB curve", "kDisplayTransferGamma22"},
    };
    return table;
}

} // namespace ptview
