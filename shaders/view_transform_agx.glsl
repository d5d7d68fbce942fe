// An AgX view transform after Troy Sobotka's AgX as Blender 4 ships it: linear Rec.709 in,
// display-linear Rec.709 out (the display encoding follows, shaders/srgb.glsl).
//   1. the inset matrix pulls every primary a little toward the achromatic axis, so that bright
//      saturated colours run to white instead of clipping into a flat hue;
//   2. log2 encoding of 16.5 stops, from 0.18 * 2^-10 to 0.18 * 2^6.5, to [0, 1] (mid grey at 10/16.5);
//   3. the sigmoid contrast curve, here as a degree-6 polynomial fit of it on [0, 1];
//   4. the outset matrix (the inset's inverse) and the curve's own 2.2 power, which make the
//      result display-linear.
// The matrices are the inset/outset pair published with the reference AgX; mat3() takes columns.

const mat3 kAgxInset = mat3(
    0.842479062253094, 0.0423282422610123, 0.0423756549057051,
    0.0784335999999992, 0.878468636469772, 0.0784336,
    0.0792237451477643, 0.0791661274605434, 0.879142973793104);
const mat3 kAgxOutset = mat3(
    1.19687900512017, -0.0528968517574562, -0.0529716355144438,
    -0.0980208811401368, 1.15190312990417, -0.0980434501171241,
    -0.0990297440797205, -0.0989611768448433, 1.15107367264116);
const float kAgxMinStops = -12.47393; // log2(0.18) - 10
const float kAgxMaxStops = 4.026069;  // log2(0.18) + 6.5

// The contrast sigmoid on the log encoding; it maps 0 to about 0 and 1 to about 1, with mid grey
// (0.606) near 0.5 and a slope that flattens into toe and shoulder.
vec3 agxContrast(vec3 x) {
    vec3 x2 = x * x;
    vec3 x4 = x2 * x2;
    return 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x - 0.00232;
}

vec3 toneMapAgx(vec3 radiance) {
    vec3 inset = kAgxInset * max(radiance, vec3(0.0));
    // 1e-10 keeps log2 finite at black; it is far below the encoding's lowest stop.
    vec3 stops = clamp(log2(max(inset, vec3(1e-10))), kAgxMinStops, kAgxMaxStops);
    vec3 encoded = (stops - kAgxMinStops) / (kAgxMaxStops - kAgxMinStops);
    // The fit dips 0.002 below zero at black; clamped so that 0 maps to 0 and the power stays real.
    vec3 curve = clamp(agxContrast(encoded), 0.0, 1.0);
    // The outset can push a saturated colour slightly negative: clamped before the power.
    return min(pow(max(kAgxOutset * curve, vec3(0.0)), vec3(2.2)), vec3(1.0));
}
