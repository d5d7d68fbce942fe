#version 410 core
// The path recorder's pass (renderer/tracer/PathRecorder.cpp): work item i = path * uVerticesPerPath +
// vertex traces sample uFirstSample + path of uPixel exactly as pathtrace_sample.glsl does, with
// the integrator's hooks (path_recorder.glsl) keeping vertex `vertex` of it. The 12 fields of the
// record do not fit the draw buffers GL 4.1 promises, so the pass runs three times, uOutputSet
// choosing the four fields each writes.
#include "frame_uniforms.glsl"
#include "constants.glsl"
#include "sampler.glsl"
#include "camera.glsl"
#include "integrator.glsl"

uniform int uWidth;
uniform int uCount;
uniform ivec2 uPixel;          // GL window coordinates: from the image's bottom-left corner
uniform int uFirstSample;
uniform int uVerticesPerPath;
uniform int uOutputSet;        // 0, 1 or 2: fields 4 * uOutputSet .. 4 * uOutputSet + 3

layout(location = 0) out vec4 outField0;
layout(location = 1) out vec4 outField1;
layout(location = 2) out vec4 outField2;
layout(location = 3) out vec4 outField3;

void main() {
    int item = int(gl_FragCoord.y) * uWidth + int(gl_FragCoord.x);
    int path = item / uVerticesPerPath;
    Sampler sampler;
    Ray ray = generatePixelRay(uvec2(uPixel), uint(uFirstSample + path), sampler);
    startRecording(item % uVerticesPerPath, ray);
    gRecord[11].xyz = item < uCount ? estimateRadiance(ray, sampler) : vec3(0.0);
    gRecord[0].w = float(gFlags);
    int first = 4 * uOutputSet;
    outField0 = gRecord[first];
    outField1 = gRecord[first + 1];
    outField2 = gRecord[first + 2];
    outField3 = gRecord[first + 3];
}
