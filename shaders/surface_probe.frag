#version 410 core
// The pixel inspector's and click-to-focus's probe: what the pinhole ray through uFilmPos (pixels
// from the image's bottom-left corner, as the camera counts them) meets first, found by the
// scene's own intersection code, textures' alpha cut-outs included. One fragment writes four
// RGBA32F texels (renderer/tracer/PathTracer.cpp, probeSurface, reads them back); a ray that leaves
// the scene writes a negative distance. Specialized like the path-tracing program.
#include "frame_uniforms.glsl"
#include "camera.glsl"
#include "intersect.glsl"

uniform vec2 uFilmPos;

layout(location = 0) out vec4 outDistances;     // along the ray, along the view direction, uv
layout(location = 1) out vec4 outPosition;      // world position, material index
layout(location = 2) out vec4 outNormalGeom;    // geometric normal, primitive kind
layout(location = 3) out vec4 outNormalShading; // shading normal, primitive index

void main() {
    Ray ray = generatePinholeRay(uFilmPos);
    Hit hit;
    if (!intersectScene(ray, hit)) {
        outDistances = vec4(-1.0, -1.0, 0.0, 0.0);
        outPosition = outNormalGeom = outNormalShading = vec4(0.0, 0.0, 0.0, -1.0);
        return;
    }
    // Small integers are exact in a float (up to 2^24).
    outDistances = vec4(hit.t, hit.t * dot(ray.direction, uCameraForward), hit.uv);
    outPosition = vec4(hit.posWorld, float(hit.material));
    outNormalGeom = vec4(hit.normalGeom, float(hit.primitive.x));
    outNormalShading = vec4(hit.normalShading, float(hit.primitive.y));
}
