// Display encodings (DisplayTransfer, renderer/settings/ToneMapper.h): display-linear [0, 1] to the
// code values a display expects.

// IEC 61966-2-1: a linear segment near black (slope 12.92), where a pure power would have an
// infinite slope, joined to an offset power 1/2.4 at 0.0031308.
vec3 encodeSrgb(vec3 linear) {
    vec3 x = clamp(linear, 0.0, 1.0);
    vec3 curve = 1.055 * pow(x, vec3(1.0 / 2.4)) - 0.055;
    return mix(curve, 12.92 * x, lessThan(x, vec3(0.0031308)));
}

// What ptview used before the sRGB curve; kept so that older files render again as they were.
vec3 encodeGamma22(vec3 linear) {
    return pow(clamp(linear, 0.0, 1.0), vec3(1.0 / 2.2));
}

vec3 encodeDisplay(vec3 linear, uint transfer) {
    return transfer == kDisplayTransferGamma22 ? encodeGamma22(linear) : encodeSrgb(linear);
}
