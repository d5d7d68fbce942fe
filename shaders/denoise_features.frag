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
// Also the emission each camera ray's path adds before it first scatters other than by a delta
// lobe: what its camera ray meets, and what it meets through mirrors, glass and smooth coats,
// exactly as the path adds it (the integrator's own phases with the same sampler, so the same
// lobes). The prepare pass takes it out of the pixel's mean, so that a light's or the sky's
// outline, and a light seen in a mirror, through glass or in a varnish, is filtered as the surface
// around it, and adds back the emission of more camera rays than the radiance has. Those come from
// a second run of this program (uCoverage), at up to Denoiser::kMaxCoverageSamples rays per pixel,
// only where such emission and a surface share a pixel's 3x3 neighbourhood, or where pixels that
// see only light differ (denoise_coverage_zone.frag).
#include "frame_uniforms.glsl"
#include "camera.glsl"
#include "intersect.glsl"
#include "bsdf.glsl"
#include "shading_frame.glsl"
#include "microfacet.glsl"
#include "media.glsl"
#include "integrator.glsl"
#include "emission_edges.glsl"

uniform sampler2D uPrevAlbedoDepth;
uniform sampler2D uPrevNormal;
uniform sampler2D uPrevEmission;
// The coverage run: only this pass's sums are written, added to the run's by blending, and only
// in the pixels denoise_coverage_zone.frag marked in the stencil (llvmpipe then skips the rest).
uniform bool uCoverage;

layout(location = 0) out vec4 outAlbedoDepth; // sums: albedo rgb, distance (m); coverage run: albedo
                                              // rgb, camera rays traced
layout(location = 1) out vec4 outNormal;      // sums: shading normal xyz, samples that met a surface
                                              // (not the environment, not an emitter); coverage
                                              // run: the emission's luminance squared (for the
                                              // noise of its mean), 0, 0, 0
layout(location = 2) out vec4 outEmission;    // sums: emission along the delta chain rgb, samples
                                              // whose light is all that emission

// Delta bounces followed before a surface counts as the first one whatever it is, and the emission
// beyond them is no longer separated: a path that long between mirrors is rare, features that stop
// there are still features, and emission left in the mean is filtered as it was.
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
// scene or meets an emitter (no surface: albedo 1, nothing to demodulate).
void sampleFeatures(Ray ray, Sampler sampler, out vec3 albedo, out vec3 normal, out float distance) {
    vec3 tint = vec3(1.0);
    distance = 0.0;
    for (int bounce = 0; bounce <= kMaxDeltaBounces; ++bounce) {
        Hit hit;
        if (!intersectSurface(ray, hit)) {
            albedo = tint;
            normal = vec3(0.0);
            distance = -1.0;
            return;
        }
        distance += hit.t;
        Material material = fetchSurfaceMaterial(hit.material, hit.uv);
        if (material.type == kMaterialEmitter) {
            // An emitter's radiance, seen directly, has no noise to take out: like the
            // environment, it is no surface for the filter.
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

// The emission a path adds before it first scatters other than by a delta lobe: where its camera
// ray lands (an emitter, the environment) and after each delta scattering that follows (a mirror,
// glass, a smooth coat), weighted as the path weighs it. The integrator's own phases
// (integrator.glsl: addEmissionFound, scatter, roulette) with the path's sampler, so the lobes
// chosen are the path's and the sum is, sample for sample, what the path added there. Unlike the
// features, glass reflects here where the path's sample reflected. `onlyEmission`: the path added
// nothing else (no light sample where a lobe is not a delta, no scattering but delta ones), so the
// sample's light is all this emission. In a scene with media the camera ray may scatter before it
// gets anywhere: nothing is separated there (0, not only emission). cameraEmissionWeight: the
// path's (emission_edges.glsl).
vec3 emissionAlongDeltaChain(Ray cameraRay, Sampler sampler, float cameraEmissionWeight, out bool onlyEmission) {
    onlyEmission = false;
    if (mediaInScene()) return vec3(0.0);
    onlyEmission = true;
    PathState path = startPath(cameraRay, cameraEmissionWeight, false);
    for (int vertex = 0; vertex <= kMaxDeltaBounces; ++vertex) {
        int bounce = path.bounce;
        Hit hit;
        if (!intersectScene(path.ray, hit)) {
            if (countsEmissionFoundAt(bounce))
                addEmissionFound(path, environmentRadiance(path.ray.direction), uEnvironmentLight, kInfinity, vec3(0.0));
            return path.radiance;
        }
        Material material = fetchSurfaceMaterial(hit.material, hit.uv);
        if (countsEmissionFoundAt(bounce)) {
            vec3 emitted = emittedRadiance(material, hit.normalGeom, -path.ray.direction);
            if (any(greaterThan(emitted, vec3(0.0)))) addEmissionFound(path, emitted, hit.light, hit.t, hit.normalGeom);
        }
        if (bounce >= lastBounce() || material.type == kMaterialEmitter) return path.radiance;
        // A light sample finds nothing through delta lobes alone; elsewhere the path adds one here.
        if (samplesLights() && !isPurelySpecular(material)) onlyEmission = false;
        if (!samplesBsdf()) return path.radiance; // `direct`: nothing after the light sample
        if (!kDeltaLobeModels) {
            onlyEmission = false; // the path scatters on, and by no delta lobe
            return path.radiance;
        }
        ShadingFrame frame = makeShadingFrame(hit.normalShading);
        if (!scatter(path, material, frame, hit, toLocal(frame, -path.ray.direction), sampler)) return path.radiance;
        if (!path.previousDelta) {
            onlyEmission = false;
            return path.radiance;
        }
        if (playsRoulette(bounce) && !survivesRoulette(path, sampler, bounce)) return path.radiance;
    }
    onlyEmission = false; // the path goes on beyond the chain followed here
    return path.radiance;
}

void main() {
    uvec2 pixel = uvec2(gl_FragCoord.xy);
    vec4 albedoDepth = vec4(0.0);
    vec4 normalSum = vec4(0.0);
    vec4 emission = vec4(0.0);
    float emissionSquares = 0.0;
    if (uFrameIndex > 0u && !uCoverage) {
        albedoDepth = texelFetch(uPrevAlbedoDepth, ivec2(pixel), 0);
        normalSum = texelFetch(uPrevNormal, ivec2(pixel), 0);
        emission = texelFetch(uPrevEmission, ivec2(pixel), 0);
    }
    // On an emission edge the render's samples take the emission their camera ray meets from it and
    // its edge rays (emission_edges.glsl): so do these, sample for sample (the same corners decide,
    // here in every pass, since these sums keep no decision). The coverage run's rays stay plain.
    uint edgeRays = 0u;
    if (!uCoverage && edgeRaysPay()) edgeRays = cornerEdgeRays(pixel);
    for (uint i = 0u; i < uSamplesPerPass; ++i) {
        Sampler sampler;
        Ray ray = generatePixelRay(pixel, uFrameIndex + i, sampler);
        vec3 albedo, normal;
        float distance;
        sampleFeatures(ray, sampler, albedo, normal, distance);
        bool onlyEmission;
        vec3 emitted = emissionAlongDeltaChain(ray, sampler, cameraEmissionWeight(edgeRays), onlyEmission);
        for (uint k = 0u; k < edgeRays; ++k)
            emitted += edgeRayEmission(pixel, edgeRayIndex(uFrameIndex + i, k, edgeRays), edgeRays);
        // A sample whose light is all emission has nothing to demodulate: albedo 0, its light is
        // all in the emission sums.
        if (onlyEmission) albedo = vec3(0.0);
        albedoDepth += vec4(albedo, uCoverage ? 1.0 : max(distance, 0.0));
        normalSum += vec4(normal, distance >= 0.0 ? 1.0 : 0.0);
        emission += vec4(emitted, onlyEmission ? 1.0 : 0.0);
        emissionSquares += luminance(emitted) * luminance(emitted);
    }
    outAlbedoDepth = albedoDepth;
    outNormal = uCoverage ? vec4(emissionSquares, 0.0, 0.0, 0.0) : normalSum;
    outEmission = emission;
}
