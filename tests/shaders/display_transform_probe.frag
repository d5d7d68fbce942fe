#version 410 core
// Runs the product's display transform (shaders/tonemap.glsl) once per texel of a ProbePass grid,
// for tests/ViewTransformTest.cpp. Input texture 0 holds one radiance per texel (rgb).
//   out0 = (displayTransform(radiance, uExposureScale, uToneMapper, uDisplayTransfer), 0)
//   out1 = (the tone mapper alone: display-linear, before the encoding, 0)
#include "tonemap.glsl"

uniform int uWidth; // fragments per row
uniform int uCount; // fragments that carry work
uniform sampler2D uItems;
uniform float uExposureScale;
uniform uint uToneMapper;
uniform uint uDisplayTransfer;

layout(location = 0) out vec4 out0;
layout(location = 1) out vec4 out1;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    out0 = vec4(0.0);
    out1 = vec4(0.0);
    if (texel.y * uWidth + texel.x >= uCount) return;
    vec3 radiance = texelFetch(uItems, texel, 0).rgb;
    out0 = vec4(displayTransform(radiance, uExposureScale, uToneMapper, uDisplayTransfer), 0.0);
    // The identity encoding is not a transfer; the linear value comes from the tone mapper alone.
    vec3 exposed = max(radiance * uExposureScale, vec3(0.0));
    out1 = vec4(uToneMapper == kToneMapperAgx ? toneMapAgx(exposed) : exposed, 0.0);
}
