// Anti-aliasing where the camera sees the edge of an emitting surface. A pixel across a lamp's
// outline is part bright, part dark: whether its camera ray finds the emission is a coin toss, far
// more variance than any light reflected in the image. On the bunny's Cornell box at 256x256 and
// 64 spp the emission the camera sees directly held half of the image's variance, nearly all of it
// in the 0.17% of pixels along the light's edge. In such a pixel a sample estimates the emission
// the camera sees directly as the mean over its own camera ray and its edge rays, more camera rays
// through the pixel (and the lens); the rest of the path is the camera ray's, as everywhere else.
// An edge ray needs only a nearest hit and its emission, no shading.
//
// A pixel is on an emission edge when the emission of the surfaces its four corners' pinhole rays
// meet differs by more than 2:1: across a lamp's outline (the corners meet different materials,
// or some meet nothing) a sample takes kOutlineEdgeRays edge rays, within one emitting surface's
// texture kTextureEdgeRays (enums.glsl, from renderer/gpudata/PassSize.h, which says why). Its
// first pass decides, from rays that are none of its samples', so the choice does not depend on
// what the samples find and every sample's estimate stays unbiased (docs/sampling.md, "Emission
// edges"); the pixel's sums keep the decision for its later passes (accumulate_sum.glsl).
// Missed: an emitter that passes between the corners (smaller than a pixel); those pixels keep
// the plain estimate. Scenes with media are left out: through a medium
// the camera sees less than the first surface's emission.
#include "accumulate_sum.glsl"
#include "camera.glsl"
#include "integrator.glsl"

const uint kEdgeRaySeed = 0x2545f491u; // the edge rays' random numbers are none of the paths'

// Whether `ray` meets a surface, and the emission that surface sends back along it and its
// material (-1 where it meets none).
bool surfaceEmissionAlong(Ray ray, out vec3 emitted, out int material) {
    Hit hit;
    emitted = vec3(0.0);
    material = -1;
    if (!intersectScene(ray, hit)) return false;
    emitted = emittedRadiance(fetchSurfaceMaterial(hit.material, hit.uv), hit.normalGeom, -ray.direction);
    material = hit.material;
    return true;
}

// Emission the camera sees along `ray`: the first surface's, or the environment's where the ray
// meets nothing.
vec3 emissionSeenAlong(Ray ray) {
    vec3 emitted;
    int material;
    return surfaceEmissionAlong(ray, emitted, material) ? emitted : environmentRadiance(ray.direction);
}

// Lights of these kinds are the emitting surfaces; a program for a scene without any compiles
// the edge rays out (light_kinds.glsl is generated per program).
bool sceneHasEmittingSurfaces() {
    return hasLightKind(kLightQuad) || hasLightKind(kLightSphere) || hasLightKind(kLightDisk) || hasLightKind(kLightTriangle);
}

// Edge rays are traced by programs for images whose passes take several samples per pixel
// (kEdgeRays, a constant of the program: PathTracer::edgeRays). The path loop traces them
// (pathtrace_sample.glsl), but in a pass of one sample they still cost the Cornell box 15% of its
// samples per second at 1280x720, mostly the first pass's corner loop, which llvmpipe runs once,
// masked, in every pass (docs/performance.md, "The path loop").
bool edgeRaysPay() {
    return kEdgeRays && sceneHasEmittingSurfaces();
}

// The corners look for emitting surfaces only: against the environment the other side of an edge
// is a surface lit by that environment, and there the plain estimate is the better one (a white
// sphere under a uniform sky is exactly as bright as the sky in every sample, silhouette included,
// which edge rays would turn into noise). Measured on the helmet and the outdoor hdr scene:
// silhouettes against the sky gained nothing and cost 10-20% of the time.
// The edge rays a sample of the pixel takes (0: not on an edge). The corners meeting one material
// that emits unevenly is an emitting texture's contrast; any other difference is an outline.
uint cornerEdgeRays(uvec2 pixel) {
    if (mediaInScene()) return 0u;
    float dimmest = kInfinity, brightest = 0.0;
    int lowestMaterial = 2147483647, highestMaterial = -1; // -1: a corner that meets nothing
    for (int corner = 0; corner < 4; ++corner) {
        vec2 filmPos = vec2(pixel) + vec2(corner & 1, corner >> 1);
        vec3 emitted;
        int material;
        surfaceEmissionAlong(generatePinholeRay(filmPos), emitted, material);
        float seen = luminance(emitted);
        dimmest = min(dimmest, seen);
        brightest = max(brightest, seen);
        lowestMaterial = min(lowestMaterial, material);
        highestMaterial = max(highestMaterial, material);
    }
    if (!(brightest > 2.0 * dimmest)) return 0u;
    return lowestMaterial == highestMaterial && lowestMaterial >= 0 ? kTextureEdgeRays : kOutlineEdgeRays;
}

// Whether the pass's samples take edge rays. A pixel's first samples are those of frame 0 (with
// adaptive sampling too): on a condition the same for every pixel llvmpipe skips the corners'
// code in later passes, where a per-pixel condition would run it for nothing.
uint pixelEdgeRays(uvec2 pixel) {
    uint edgeRays = 0u;
    if (!edgeRaysPay()) return edgeRays;
    if (uFrameIndex == 0u) edgeRays = cornerEdgeRays(pixel);
    else edgeRays = storedEdgeRays(ivec2(pixel));
    return edgeRays;
}

// Weight of the emission a path's own camera ray finds: one of 1 + edgeRays rays.
float cameraEmissionWeight(uint edgeRays) {
    return 1.0 / float(1u + edgeRays);
}

// The sampler of edge ray `ray` of a pixel whose samples take edgeRays (at least 1), whose camera
// ray generatePixelRay makes. The rays are numbered on across the pixel's samples (edgeRayIndex),
// so that all of a pixel's edge rays are one well-spread sequence of their own, a prefix of it:
// numbered in blocks of the most a sample takes, a pixel of 4 would use a quarter of every 16
// consecutive Sobol' points, which fill only part of the pixel.
Sampler createEdgeRaySampler(uvec2 pixel, uint ray, uint edgeRays) {
    return createSampler(pixel, ray, uSeed ^ kEdgeRaySeed, kSamplerMode, uSampleBudget * edgeRays);
}

// The number of edge ray k (0 ... edgeRays - 1) of sample sampleIndex of a pixel whose samples
// take edgeRays: an aligned block of them per sample (edgeRays is a power of two).
uint edgeRayIndex(uint sampleIndex, uint k, uint edgeRays) {
    return sampleIndex * edgeRays + k;
}

// What edge ray `ray` of a pixel whose samples take edgeRays adds to its sample: its share of the
// emission the camera sees.
vec3 edgeRayEmission(uvec2 pixel, uint ray, uint edgeRays) {
    return clampContribution(emissionSeenAlong(generatePixelRay(pixel, createEdgeRaySampler(pixel, ray, edgeRays)))) *
           (lightPathWeight(0, startPathHistory(), false) * cameraEmissionWeight(edgeRays));
}
