#version 410 core
// Runs the product's ray queries (shaders/intersect.glsl: analytic shapes and the mesh BVH) once
// per texel of a ProbePass grid, for tests/MeshTest.cpp. Input 0: (ray origin, tMax); input 1:
// (ray direction, -). Writes
//   out0 = (t of the nearest hit or -1, its material, its light, normalGeom.x),
//   out1 = (normalGeom.y, normalGeom.z, occluded(ray, tMax, -1) ? 1 : 0, -),
//   out2 = (normalShading, -).
#include "intersect.glsl"

uniform int uWidth; // fragments per row
uniform int uCount; // fragments that carry work
uniform sampler2D uOrigins;
uniform sampler2D uDirections;

layout(location = 0) out vec4 out0;
layout(location = 1) out vec4 out1;
layout(location = 2) out vec4 out2;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    out0 = vec4(-1.0, 0.0, 0.0, 0.0);
    out1 = vec4(0.0);
    out2 = vec4(0.0);
    if (texel.y * uWidth + texel.x >= uCount) return;
    vec4 originAndTMax = texelFetch(uOrigins, texel, 0);
    Ray ray = Ray(originAndTMax.xyz, texelFetch(uDirections, texel, 0).xyz);
    Hit hit;
    if (intersectScene(ray, hit)) {
        out0 = vec4(hit.t, float(hit.material), float(hit.light), hit.normalGeom.x);
        out1.xy = hit.normalGeom.yz;
        out2 = vec4(hit.normalShading, 0.0);
    }
    out1.z = occluded(ray, originAndTMax.w, -1) ? 1.0 : 0.0;
}
