// The debug views of renderer/settings/DebugView.h: the first surface the camera ray hits, seen through
// its shading normal (mapped from [-1, 1] to [0, 1]) or its albedo (the material's colour; an
// emitter's radiance scaled to at most 1), or its distance from the ray's origin on the lens (in
// all three channels; metres, as the scene's units). Nothing hit: black (0, also for depth).
// Media's null boundaries are no surface: the views see through a fog box as through air.
#include "intersect.glsl"
#include "media.glsl"
// kDebugViewRadiance, ...: generated from the C++ table (renderer/gpu/GlslEnums.cpp).
#include "enums.glsl"

vec3 debugViewValue(Ray ray, uint view) {
    Hit hit;
    if (!intersectSurface(ray, hit)) return vec3(0.0);
    if (view == kDebugViewNormals) return 0.5 * hit.normalShading + 0.5;
    if (view == kDebugViewDepth) return vec3(hit.t); // the ray's direction is unit length
    Material material = fetchMaterial(hit.material);
    if (material.type == kMaterialEmitter) return material.radiance / max(1e-6, max(material.radiance.r, max(material.radiance.g, material.radiance.b)));
    return material.color;
}
