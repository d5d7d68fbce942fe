#version 410 core
// The path recorder's pass (renderer/tracer/PathRecorder.cpp): work item i = path * uVerticesPerPath +
// vertex traces sample uFirstSample + path of uPixel exactly as pathtrace_sample.glsl does, with
// the integrator's hooks (path_recorder.glsl) keeping vertex `vertex` of it. The kRecordFields fields
// of the record do not fit the draw buffers GL 4.1 promises, so the pass runs once per four of
// them, uOutputSet choosing the four fields each writes (zeros past the last).
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
uniform int uOutputSet;        // fields 4 * uOutputSet .. 4 * uOutputSet + 3

layout(location = 0) out vec4 outField0;
layout(location = 1) out vec4 outField1;
layout(location = 2) out vec4 outField2;
layout(location = 3) out vec4 outField3;

vec4 recordField(int field) { return field < kRecordFields ? gRecord[field] : vec4(0.0); }

void main() {
    int item = int(gl_FragCoord.y) * uWidth + int(gl_FragCoord.x);
    int path = item / uVerticesPerPath;
    Sampler sampler;
    Ray ray = generatePixelRay(uvec2(uPixel), uint(uFirstSample + path), sampler);
    startRecording(item % uVerticesPerPath, ray);
    gRecord[11].xyz = item < uCount ? estimateRadiance(ray, sampler) : vec3(0.0);
    gRecord[0].w = float(gFlags);
    int first = 4 * uOutputSet;
    outField0 = recordField(first);
    outField1 = recordField(first + 1);
    outField2 = recordField(first + 2);
    outField3 = recordField(first + 3);
}
