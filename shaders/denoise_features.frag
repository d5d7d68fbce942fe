#version 410 core
// The denoiser's features (docs/denoising.md): for each of a pass's uSamplesPerPass camera rays
// (the same rays, sample for sample, as the path-tracing passes: generatePixelRay), the first
// surface that is not a pure mirror or smooth glass, reached by following the delta bounces the
// way the path would (Open Image Denoise asks for exactly this: a reflection's features are those
// of what it reflects, so the filter keeps the reflected edges). Its albedo (the material's
// colour, textures included, times the tint of the delta bounces before it), shading normal, and
// distance along the chain. Added to the previous sums (uPrev*, frame 0 starts afresh), as the
// radiance is. Media's null boundaries are no surface: the features are those of what lies behind a
// fog box's faces. Specialized like the path-tracing program of the scene.
//
// Also the emission each camera ray meets first, exactly what the path adds there
// (emissionAddedByCameraRay): the prepare pass takes it out of the pixel's mean, so that a light's
// or the sky's outline is filtered as the surface beside it, and adds back the emission of more
// camera rays than the radiance has. Those come from a second run of this program (uCoverage), at
// up to Denoiser::kMaxCoverageSamples rays per pixel, only where an emitter or the environment and
// a surface share a pixel's 3x3 neighbourhood, or where pixels that see only light differ
// (denoise_coverage_zone.frag).
#include "frame_uniforms.glsl"
#include "camera.glsl"
#include "intersect.glsl"
#include "bsdf.glsl"
#include "shading_frame.glsl"
#include "microfacet.glsl"
#include "media.glsl"
#include "integrator.glsl"

uniform sampler2D uPrevAlbedoDepth;
uniform sampler2D uPrevNormal;
uniform sampler2D uPrevEmission;
// The coverage run: only this pass's sums are written, added to the run's by blending, and only
// in the pixels denoise_coverage_zone.frag marked in the stencil (llvmpipe then skips the rest).
uniform bool uCoverage;

layout(location = 0) out vec4 outAlbedoDepth; // sums: albedo rgb, distance (m); coverage run: albedo
                                              // rgb, camera rays traced
layout(location = 1) out vec4 outNormal;      // sums: shading normal xyz, samples that met a surface
                                              // (not the environment, not an emitter)
layout(location = 2) out vec4 outEmission;    // sums: emission met first rgb, samples that met an
                                              // emitter or the environment first (whose light is
                                              // all that emission)

// Delta bounces followed before a surface counts as the first one whatever it is: a path that
// long between mirrors is rare, and features that stop there are still features.
const int kMaxDeltaBounces = 4;

// Whether every direction a material scatters to is a delta lobe: the filter looks through it.
bool isPurelySpecular(Material material) {
    if (material.type == kMaterialMirror || material.type == kMaterialSpecularTransmission || material.type == kMaterialGlass)
        return true;
    bool isSmooth = ggxIsEffectivelySmooth(ggxAlpha(material.roughness));
    if (material.type == kMaterialMetal) return isSmooth;
    if (material.type == kMaterialPrincipled) return isSmooth && (material.metallic >= 1.0 || material.transmission >= 1.0);
    return false;
}

// Albedo, normal and distance of one camera ray; normal 0 and distance -1 where it leaves the
// scene or meets an emitter. `emitted`: the emission the path adds where the camera ray itself
// lands, and `lightFirst` where that is an emitter (which reflects nothing) or the environment:
// albedo 0 then, the sample's light is all in `emitted`. In a scene with media the camera ray may
// scatter before it gets there, so nothing is separated (the light counts as behind a mirror:
// albedo 1, no surface).
void sampleFeatures(Ray ray, Sampler sampler, out vec3 albedo, out vec3 normal, out float distance,
                    out vec3 emitted, out bool lightFirst) {
    vec3 tint = vec3(1.0);
    distance = 0.0;
    emitted = vec3(0.0);
    lightFirst = false;
    bool separates = !mediaInScene();
    for (int bounce = 0; bounce <= kMaxDeltaBounces; ++bounce) {
        Hit hit;
        if (!intersectSurface(ray, hit)) {
            if (bounce == 0 && separates) {
                emitted = emissionAddedByCameraRay(ray, environmentRadiance(ray.direction));
                lightFirst = true;
                albedo = vec3(0.0);
                normal = vec3(0.0);
                distance = -1.0;
                return;
            }
            // The environment: nothing to demodulate (albedo 1), no surface to compare normals with.
            albedo = tint;
            normal = vec3(0.0);
            distance = -1.0;
            return;
        }
        distance += hit.t;
        Material material = fetchSurfaceMaterial(hit.material, hit.uv);
        if (bounce == 0 && separates) {
            emitted = emissionAddedByCameraRay(ray, emittedRadiance(material, hit.normalGeom, -ray.direction));
            if (material.type == kMaterialEmitter) {
                lightFirst = true;
                albedo = vec3(0.0);
                normal = vec3(0.0);
                distance = -1.0;
                return;
            }
        }
        if (material.type == kMaterialEmitter) {
            // An emitter's radiance, seen directly, has no noise to take out: like the
            // environment, it is no surface for the filter (albedo 1, no normal, no distance).
            albedo = tint;
            normal = vec3(0.0);
            distance = -1.0;
            return;
        }
        normal = hit.normalShading;
        albedo = tint * material.color;
        if (!kPurelySpecularModels || bounce == kMaxDeltaBounces || !isPurelySpecular(material)) return;
        ShadingFrame frame = makeShadingFrame(hit.normalShading);
        vec3 woLocal = toLocal(frame, -ray.direction);
        // Glass both reflects and refracts; the features follow the refraction, whatever the
        // sample (uLobe just below 1 picks the last lobe), so that every sample of a pixel sees the
        // same surface through it: what lies behind glass is what an artist looks at, and a pixel
        // whose samples disagreed would have to be left unfiltered (an outline, prepare's rule).
        BsdfSample bs = sampleBsdf(material, woLocal, 0.99999994, samplerGet2D(sampler, bsdfDimension(bounce)));
        if (bs.pdfSolidAngle == 0.0) return; // the surface itself, then
        tint *= bs.weight;
        ray = spawnRay(hit.posWorld, hit.normalGeom, toWorld(frame, bs.wiLocal));
    }
}

void main() {
    uvec2 pixel = uvec2(gl_FragCoord.xy);
    vec4 albedoDepth = vec4(0.0);
    vec4 normalSum = vec4(0.0);
    vec4 emission = vec4(0.0);
    if (uFrameIndex > 0u && !uCoverage) {
        albedoDepth = texelFetch(uPrevAlbedoDepth, ivec2(pixel), 0);
        normalSum = texelFetch(uPrevNormal, ivec2(pixel), 0);
        emission = texelFetch(uPrevEmission, ivec2(pixel), 0);
    }
    for (uint i = 0u; i < uSamplesPerPass; ++i) {
        Sampler sampler;
        Ray ray = generatePixelRay(pixel, uFrameIndex + i, sampler);
        vec3 albedo, normal, emitted;
        float distance;
        bool lightFirst;
        sampleFeatures(ray, sampler, albedo, normal, distance, emitted, lightFirst);
        albedoDepth += vec4(albedo, uCoverage ? 1.0 : max(distance, 0.0));
        normalSum += vec4(normal, distance >= 0.0 ? 1.0 : 0.0);
        emission += vec4(emitted, lightFirst ? 1.0 : 0.0);
    }
    outAlbedoDepth = albedoDepth;
    outNormal = normalSum;
    outEmission = emission;
}
