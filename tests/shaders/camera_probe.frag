#version 410 core
// Runs the product's camera (shaders/camera.glsl, with its thin lens) once per texel of a
// ProbePass grid, for tests/CameraTest.cpp. Item i is pixel (i % W, (i / W) % H) of the W x H
// image in the FrameBlock, sample i / (W * H) of it, at the pixel's centre. Writes
//   out0 = (pinhole ray origin, the lens sample's u.x)   out1 = (pinhole ray direction, u.y)
//   out2 = (camera ray origin, -)                        out3 = (camera ray direction, -)
#include "camera.glsl"

uniform int uWidth; // fragments per row
uniform int uCount; // fragments that carry work

layout(location = 0) out vec4 out0;
layout(location = 1) out vec4 out1;
layout(location = 2) out vec4 out2;
layout(location = 3) out vec4 out3;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    int item = texel.y * uWidth + texel.x;
    out0 = out1 = out2 = out3 = vec4(0.0);
    if (item >= uCount) return;
    int pixels = uImageSize.x * uImageSize.y;
    ivec2 pixel = ivec2(item % uImageSize.x, (item % pixels) / uImageSize.x);
    Sampler sampler = createSampler(uvec2(pixel), uint(item / pixels), uSeed, uSamplerMode, uSampleBudget);
    vec2 filmPos = vec2(pixel) + 0.5;
    Ray pinhole = generatePinholeRay(filmPos);
    Ray camera = generateCameraRay(filmPos, sampler);
    vec2 u = samplerGet2D(sampler, kDimensionLens);
    out0 = vec4(pinhole.origin, u.x);
    out1 = vec4(pinhole.direction, u.y);
    out2 = vec4(camera.origin, 0.0);
    out3 = vec4(camera.direction, 0.0);
}
