#version 410 core
// The pixel inspector's and click-to-focus's probe: what the pinhole ray through uFilmPos (pixels
// from the image's bottom-left corner, as the camera counts them) meets first, found by the
// scene's own intersection code, textures' alpha cut-outs included; media's null boundaries let
// it through, as they let every ray. One fragment writes four RGBA32F texels, the set uOutputSet
// chooses (renderer/tracer/PathTracer.cpp, probeSurface and probeCameraRayMedia, reads them back):
//   set 0, the first surface: distances (along the ray, along the view direction, uv); position,
//     material index; geometric normal, primitive kind; shading normal, primitive index. A ray
//     that leaves the scene writes a negative distance.
//   set 1, the media on the way (CameraRayMedia): the materials of the first four null boundaries
//     crossed (-1 past the last); their distances; the media around the eye, outermost first (-1
//     past the last); how many boundaries are crossed in all, how many media are around the eye.
// Specialized like the path-tracing program.
#include "frame_uniforms.glsl"
#include "camera.glsl"
#include "intersect.glsl"
#include "media.glsl"

uniform vec2 uFilmPos;
uniform int uOutputSet;

layout(location = 0) out vec4 outField0;
layout(location = 1) out vec4 outField1;
layout(location = 2) out vec4 outField2;
layout(location = 3) out vec4 outField3;

// Small integers are exact in a float (up to 2^24).
void probeMedia(Ray ray) {
    ivec4 materials;
    vec4 distances;
    int crossings = nullBoundariesBefore(ray, materials, distances);
    MediumStack around = cameraMediumStack();
    outField0 = vec4(materials);
    outField1 = distances;
    for (int i = 0; i < 4; ++i) outField2[i] = i < around.depth ? float(around.materials[i]) : -1.0;
    outField3 = vec4(float(crossings), float(around.depth), 0.0, 0.0);
}

void main() {
    Ray ray = generatePinholeRay(uFilmPos);
    if (uOutputSet == 1) {
        probeMedia(ray);
        return;
    }
    Hit hit;
    if (!intersectSurface(ray, hit)) {
        outField0 = vec4(-1.0, -1.0, 0.0, 0.0);
        outField1 = outField2 = outField3 = vec4(0.0, 0.0, 0.0, -1.0);
        return;
    }
    outField0 = vec4(hit.t, hit.t * dot(ray.direction, uCameraForward), hit.uv);
    outField1 = vec4(hit.posWorld, float(hit.material));
    outField2 = vec4(hit.normalGeom, float(hit.primitive.x));
    outField3 = vec4(hit.normalShading, float(hit.primitive.y));
}
