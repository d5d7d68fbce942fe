// Display transform: exposure, then a tone mapper, then the display encoding (sRGB, or gamma 2.2
// for files written before it).
// kToneMapperReinhard, ...: generated from the table of renderer/settings/ToneMapper.h (GlslEnums.cpp).
#include "enums.glsl"
#include "srgb.glsl"
#include "view_transform_agx.glsl"
#include "view_transform_ocio.glsl"

vec3 toneMapReinhard(vec3 radiance) {
    return radiance / (1.0 + radiance);
}

// Krzysztof Narkowicz's rational fit of the ACES reference rendering + output transforms: a
// filmic toe and shoulder that keeps more contrast than Reinhard and reaches white at about 10.
vec3 toneMapAces(vec3 radiance) {
    vec3 x = radiance;
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

vec3 displayTransform(vec3 radiance, float exposureScale, uint toneMapper, uint transfer) {
    vec3 exposed = max(radiance * exposureScale, vec3(0.0));
    if (toneMapper == kToneMapperOcio) return ocioView(exposed); // display-encoded already
    vec3 mapped = toneMapper == kToneMapperAces ? toneMapAces(exposed)
                : toneMapper == kToneMapperAgx ? toneMapAgx(exposed)
                : toneMapper == kToneMapperClamp ? exposed
                : toneMapReinhard(exposed);
    return encodeDisplay(mapped, transfer);
}
