// Thin lens (docs/camera.md). The lens is a uniform disk of radius uApertureRadius around the eye,
// in the plane spanned by uCameraRight and uCameraUp; the plane in focus is orthogonal to the view
// direction at uFocusDistance. A ray leaves a point of the lens towards the point of the focus
// plane that the pinhole ray of the same film position reaches, so that plane is imaged sharply
// and a point at distance d (along the view direction) blurs into a disk that covers, on the
// focus plane, a diameter of 2 * uApertureRadius * |d - uFocusDistance| / d.
//
// The lens position is its own sampler dimension (kDimensionLens), drawn through the concentric
// mapping, so stratified and sobol samplers stratify the aperture.
#include "frame_uniforms.glsl"
#include "ray.glsl"
#include "sampler.glsl"
#include "warps.glsl"

Ray refractThroughLens(Ray pinhole, Sampler sampler) {
    // The uber-shader runs this for pinhole cameras too: leave their rays exactly as they were.
    if (uApertureRadius == 0.0) return pinhole;
    vec3 focusPoint = pinhole.origin + pinhole.direction * (uFocusDistance / dot(pinhole.direction, uCameraForward));
    vec2 lens = uApertureRadius * sampleUniformDiskConcentric(samplerGet2D(sampler, kDimensionLens));
    vec3 lensPoint = pinhole.origin + lens.x * uCameraRight + lens.y * uCameraUp;
    return Ray(lensPoint, normalize(focusPoint - lensPoint));
}
