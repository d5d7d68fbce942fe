#version 410 core
// Click-to-focus: how far the surface under a film position is, along the view direction. One
// fragment traces the pinhole ray through uFilmPos (pixels from the image's bottom-left corner, as
// the camera counts them) with the scene's own intersection code, textures' alpha cut-outs
// included, and writes that distance, or -1 when the ray leaves the scene. Specialized like the
// path-tracing program (renderer/PathTracer.cpp, focusDistanceAt).
#include "frame_uniforms.glsl"
#include "camera.glsl"
#include "intersect.glsl"

uniform vec2 uFilmPos;

layout(location = 0) out vec4 outDistance;

void main() {
    Ray ray = generatePinholeRay(uFilmPos);
    Hit hit;
    outDistance = vec4(intersectScene(ray, hit) ? hit.t * dot(ray.direction, uCameraForward) : -1.0);
}
