// The four integrators, chosen by kIntegrator (specialization.glsl: a constant per program):
//
//   naive   BSDF sampling only; emission counts when a path happens to hit it.
//   direct  emission seen directly, plus one bounce of light sampling (next-event estimation)
//           with a shadow ray. Nothing reaches the camera through mirrors or glass.
//   mis     direct lighting from light sampling AND BSDF sampling at the first surface, combined
//           by the power heuristic.
//   full    global illumination: MIS next-event estimation at every non-specular vertex, BSDF
//           sampling to continue, emission found by a BSDF sample weighted against the light
//           sampling that could have found it (weight 1 after a delta lobe, which light sampling
//           cannot produce), and unbiased Russian roulette after a few bounces.
//
// uMaxDepth bounds the number of scattering events of every path, for all four.
// uRadianceClamp > 0 (firefly control, biased) caps what each path vertex adds (clampContribution).
#include "frame_uniforms.glsl"
#include "specialization.glsl"
#include "sampler.glsl"
#include "intersect.glsl"
#include "bsdf.glsl"
#include "shading_frame.glsl"
#include "emission.glsl"
#include "lights.glsl"
#include "environment.glsl"
#include "media.glsl"
#include "warps.glsl"
#include "light_paths.glsl"
#include "path_recorder.glsl"
// kIntegratorNaive, ...: generated from the C++ table (renderer/gpu/GlslEnums.cpp).
#include "enums.glsl"

// Russian roulette as particle transport's weight window: from kRussianRouletteStart scattering
// events on, a path whose weight (its throughput's largest component) is below
// kRouletteSurvivalWeight survives with probability weight / kRouletteSurvivalWeight and goes on
// with exactly that weight. A path that has lost half its weight costs more than it is worth, and
// a survivor never weighs more than 0.5 where roulette played: the rule this replaced (survive
// with the weight itself) lifted survivors to 1, fireflies twice as bright. On the bunny's Cornell
// box at 256x256 and 64 spp it gives 1.09x the efficiency (1 / variance x time), the glass
// spheres' box 1.27x; Cycles' time to equal error 0.75x -> 0.69x. The fog's room loses 9%: its
// haze keeps a path's weight above 0.5 for a dozen dim scattering events (docs/performance.md,
// "Russian roulette as a weight window").
// Not before the fourth event: the first bounces are where most light, and the rare bright paths,
// are found. From the second event on the Cornell boxes gained a little more (1.15x), but the
// helmet's dark metal then played at its first bounces with small odds, and the fireflies it
// finds at its second and third (the studio map's lamps) came back 1 / odds as bright: 2.3x the
// true error at 256 spp. Weights of 1/4, 1/3, 2/3 and 1 measured worse than 0.5.
const int kRussianRouletteStart = 4;
const float kRouletteSurvivalWeight = 0.5;

// Shading normals bend the hemisphere a BSDF sees away from the true surface. A pair of directions
// is used only when it is on the same sides of the surface for both normals; otherwise light
// would leak through (or be reflected by) the geometry, so such a sample counts as failed.
bool consistentSides(vec3 woWorld, vec3 wiWorld, Hit hit) {
    if (hit.normalShading == hit.normalGeom) return true;
    bool reflectGeom = dot(woWorld, hit.normalGeom) * dot(wiWorld, hit.normalGeom) > 0.0;
    bool reflectShading = dot(woWorld, hit.normalShading) * dot(wiWorld, hit.normalShading) > 0.0;
    return reflectGeom == reflectShading;
}

float powerHeuristic(float pdfChosen, float pdfOther) {
    float a = pdfChosen * pdfChosen;
    float b = pdfOther * pdfOther;
    return a + b > 0.0 ? a / (a + b) : 0.0;
}

// One light sample from the shading point: f * Le * |cos| / pdf, weighted against BSDF sampling
// when useMis (the BSDF has a non-delta part there); times the media's transmittance on the way.
vec3 estimateDirectLighting(Material material, ShadingFrame frame, Hit hit, vec3 woLocal, Sampler sampler,
                            int bounce, bool useMis, MediumStack media) {
    if (uLightCount == 0) return vec3(0.0);
    int light = chooseLight(samplerGet1D(sampler, lightChoiceDimension(bounce)));
    float selection = lightSelectionProbability(light);
    LightSample ls = sampleLight(light, hit.posWorld, samplerGet2D(sampler, lightPositionDimension(bounce)));
    recordLightSample(bounce, light, selection, ls, material, frame, woLocal, hit);
    if (ls.pdfSolidAngle <= 0.0 || selection <= 0.0 || all(equal(ls.radiance, vec3(0.0)))) return vec3(0.0);
    vec3 wiLocal = toLocal(frame, ls.wi);
    if (!consistentSides(toWorld(frame, woLocal), ls.wi, hit)) return vec3(0.0);
    vec3 f = bsdfF(material, woLocal, wiLocal);
    if (all(equal(f, vec3(0.0)))) return vec3(0.0);
    Ray shadowRay = spawnRay(hit.posWorld, hit.normalGeom, ls.wi);
    vec3 transmittance = vec3(1.0);
    bool blocked;
    if (mediaInScene()) {
        transmittance = shadowTransmittance(shadowRay, ls.distance, light,
                                            mediaToward(media, hit.material, hit.normalGeom, toWorld(frame, woLocal), ls.wi));
        blocked = all(equal(transmittance, vec3(0.0)));
    } else {
        blocked = occluded(shadowRay, ls.distance, light);
    }
    recordShadowRay(bounce, blocked, transmittance);
    if (blocked) return vec3(0.0);
    float pdfLight = selection * ls.pdfSolidAngle;
    // A delta light has no density to weigh against: only light sampling can find it.
    float weight = useMis && !ls.isDelta ? powerHeuristic(pdfLight, bsdfPdf(material, woLocal, wiLocal)) : 1.0;
    recordLightWeight(bounce, weight);
    vec3 estimate = f * ls.radiance * (absCosTheta(wiLocal) * weight / pdfLight);
    return mediaInScene() ? estimate * transmittance : estimate;
}

// The same from a point where a medium scatters: the phase function in place of f |cos|.
vec3 estimateMediumDirectLighting(MediumVertex vertex, vec3 directionIn, MediumStack media, Sampler sampler,
                                  int bounce, bool useMis) {
    if (uLightCount == 0) return vec3(0.0);
    int light = chooseLight(samplerGet1D(sampler, lightChoiceDimension(bounce)));
    float selection = lightSelectionProbability(light);
    LightSample ls = sampleLight(light, vertex.posWorld, samplerGet2D(sampler, lightPositionDimension(bounce)));
    recordMediumLightSample(bounce, light, selection, ls, vertex, directionIn);
    if (ls.pdfSolidAngle <= 0.0 || selection <= 0.0 || all(equal(ls.radiance, vec3(0.0)))) return vec3(0.0);
    vec3 transmittance = shadowTransmittance(Ray(vertex.posWorld, ls.wi), ls.distance, light, media);
    bool blocked = all(equal(transmittance, vec3(0.0)));
    recordShadowRay(bounce, blocked, transmittance);
    if (blocked) return vec3(0.0);
    float phase = henyeyGreensteinPdf(dot(directionIn, ls.wi), vertex.medium.g);
    float pdfLight = selection * ls.pdfSolidAngle;
    float weight = useMis && !ls.isDelta ? powerHeuristic(pdfLight, phase) : 1.0;
    recordLightWeight(bounce, weight);
    return transmittance * ls.radiance * (phase * weight / pdfLight);
}

// Firefly control: a contribution to the pixel (throughput x emission, or throughput x one light
// sample's estimate) whose largest component exceeds uRadianceClamp is scaled down to it, keeping
// its hue. Biased: the energy cut off is lost, not moved. uRadianceClamp 0 leaves it as it is.
vec3 clampContribution(vec3 contribution) {
    float largest = max(contribution.r, max(contribution.g, contribution.b));
    return uRadianceClamp > 0.0 && largest > uRadianceClamp ? contribution * (uRadianceClamp / largest) : contribution;
}

// MIS weight of emission reached by a BSDF sample of density pdfBsdf from previousPos.
float emissionWeight(int light, vec3 previousPos, vec3 wi, float hitDistance, vec3 hitNormal, float pdfBsdf) {
    if (light < 0) return 1.0; // not in the light table: light sampling never finds it
    float pdfLight = lightSelectionProbability(light) * lightPdf(light, previousPos, wi, hitDistance, hitNormal);
    return powerHeuristic(pdfBsdf, pdfLight);
}

// A path under construction: what extendPath carries from one bounce to the next. Kept in
// a struct so that a program can trace several paths one after the other in one loop
// (pathtrace_sample.glsl), starting the next path in a SIMD lane as soon as its last one ends.
struct PathState {
    Ray ray;
    int bounce;               // scattering events so far
    vec3 radiance;            // what the path has gathered
    vec3 throughput;
    vec3 previousPos;
    float previousPdf;        // solid-angle density of the BSDF sample that made this ray
    bool previousDelta;       // the camera ray counts as delta: nothing else could find it
    PathHistory history;      // for the light-path views (light_paths.glsl)
    MediumStack media;        // the media the ray is in (media.glsl)
    float cameraEmissionWeight; // of the emission the camera ray itself finds: below 1 where
                                // more camera rays share that estimate (emission_edges.glsl)
    bool emissionOnly;          // an edge ray: the emission its camera ray meets, and no more
};

PathState startPath(Ray cameraRay, float cameraEmissionWeight, bool emissionOnly) {
    return PathState(cameraRay, 0, vec3(0.0), vec3(1.0), cameraRay.origin, 0.0, true, startPathHistory(),
                     cameraMediumStack(), cameraEmissionWeight, emissionOnly);
}

PathState startPath(Ray cameraRay) {
    return startPath(cameraRay, 1.0, false);
}

// ---- What each integrator does ------------------------------------------------------------------
//           light sample   emission the path runs into          scatters at          roulette
//   naive   no             counted, weight 1                    up to uMaxDepth      no
//   direct  yes, weight 1  counted where the camera sees it     the first surface:   no
//                                                               light sample only
//   mis     yes, MIS       counted, MIS                         the first surface    no
//   full    yes, MIS       counted, MIS                         up to uMaxDepth      yes
// kIntegrator is a constant of the program (specialization.glsl), so each predicate below is too,
// and the compiler keeps only the chosen integrator's code.

// Next-event estimation: a light sample and its shadow ray at each surface.
bool samplesLights() { return kIntegrator != kIntegratorNaive; }

// Light sampling and BSDF sampling both find emission, weighted by the power heuristic.
bool weighsByMis() { return kIntegrator == kIntegratorMis || kIntegrator == kIntegratorFull; }

// `direct` counts only what the camera sees: light sampling covers the next bounce, and a BSDF
// sample finding the same light would count it twice.
bool countsEmissionFoundAt(int bounce) { return bounce == 0 || !samplesLights() || weighsByMis(); }

// `direct` and `mis` estimate the light at the first surface only.
int lastBounce() {
    return kIntegrator == kIntegratorFull || kIntegrator == kIntegratorNaive ? uMaxDepth : min(uMaxDepth, 1);
}

// `direct` takes no BSDF sample: the light sample was all it wanted of the surface.
bool samplesBsdf() { return kIntegrator != kIntegratorDirect; }

bool playsRoulette(int bounce) { return kIntegrator == kIntegratorFull && bounce + 1 >= kRussianRouletteStart; }

// ---- The phases of a bounce -------------------------------------------------------------------

// Emission the path ran into, a surface's or (light kInfinity away, normal 0) the environment's
// where the ray escaped: weighted against the light sampling that could have found it too.
void addEmissionFound(inout PathState path, vec3 emitted, int light, float hitDistance, vec3 hitNormal) {
    int bounce = path.bounce;
    float weight = (!samplesLights() || path.previousDelta) ? 1.0
                 : emissionWeight(light, path.previousPos, path.ray.direction, hitDistance, hitNormal, path.previousPdf);
    recordEmissionWeight(bounce, weight, emitted);
    weight *= lightPathWeight(bounce, path.history, bounce > 0);
    vec3 added = clampContribution(path.throughput * emitted * weight) * (bounce == 0 ? path.cameraEmissionWeight : 1.0);
    recordEmission(bounce, added);
    path.radiance += added;
}

void addDirectLighting(inout PathState path, Material material, ShadingFrame frame, Hit hit, vec3 woLocal,
                       Sampler sampler) {
    int bounce = path.bounce;
    vec3 added = clampContribution(path.throughput * estimateDirectLighting(material, frame, hit, woLocal, sampler, bounce,
                                                                            weighsByMis(), path.media)) *
                 lightPathWeight(bounce + 1, path.history, false);
    recordDirectLighting(bounce, added);
    path.radiance += added;
}

// The BSDF sample that makes the next ray. False: there is none (the sample failed, or it
// carries nothing).
bool scatter(inout PathState path, Material material, ShadingFrame frame, Hit hit, vec3 woLocal, Sampler sampler) {
    int bounce = path.bounce;
    BsdfSample bs = sampleBsdf(material, woLocal, samplerGet1D(sampler, bsdfLobeDimension(bounce)),
                               samplerGet2D(sampler, bsdfDimension(bounce)));
    recordBsdfSample(bounce, bs, material, frame, woLocal);
    if (bs.pdfSolidAngle == 0.0) return false;
    vec3 wiWorld = toWorld(frame, bs.wiLocal);
    if (!consistentSides(-path.ray.direction, wiWorld, hit)) return false;
    path.throughput *= bs.weight; // weight already holds f*|cos|/pdf
    if (all(equal(path.throughput, vec3(0.0)))) return false;
    if (mediaInScene()) path.media = mediaToward(path.media, hit.material, hit.normalGeom, -path.ray.direction, wiWorld);
    path.previousPos = hit.posWorld;
    path.previousPdf = bs.pdfSolidAngle;
    path.previousDelta = bs.isDelta;
    recordScattering(path.history, bs.isDelta);
    path.ray = spawnRay(hit.posWorld, hit.normalGeom, wiWorld);
    path.bounce = bounce + 1;
    return true;
}

// Russian roulette after the sample of `bounce`: a weight below kRouletteSurvivalWeight survives
// with probability weight / kRouletteSurvivalWeight.
bool survivesRoulette(inout PathState path, Sampler sampler, int bounce) {
    float weight = max(path.throughput.r, max(path.throughput.g, path.throughput.b));
    float survival = min(1.0, weight / kRouletteSurvivalWeight);
    bool ended = samplerGet1D(sampler, russianRouletteDimension(bounce)) >= survival;
    recordRoulette(bounce, survival, ended);
    if (ended) return false;
    path.throughput /= survival; // unbiased: no clamp on 1/survival
    return true;
}

// A medium scattered the path at `vertex`: next-event estimation with the phase function, and a
// phase-function sample for the next ray (its weight, phase / pdf, is 1). A scattering event is a
// bounce like a surface's: it counts towards uMaxDepth, roulette and the light-path filters.
bool scatterInMedium(inout PathState path, MediumVertex vertex, Sampler sampler) {
    int bounce = path.bounce;
    recordMediumScattering(bounce, vertex, path.media, path.ray, path.throughput);
    if (bounce >= lastBounce()) return false;
    if (samplesLights()) {
        vec3 added = clampContribution(path.throughput * estimateMediumDirectLighting(vertex, path.ray.direction, path.media,
                                                                                      sampler, bounce, weighsByMis())) *
                     lightPathWeight(bounce + 1, path.history, false);
        recordDirectLighting(bounce, added);
        path.radiance += added;
    }
    if (!samplesBsdf()) return false;
    // g > 0 scatters forward: the phase function's z is the direction the light travelled.
    vec3 wiLocal = sampleHenyeyGreenstein(samplerGet2D(sampler, bsdfDimension(bounce)), vertex.medium.g);
    path.previousPos = vertex.posWorld;
    path.previousPdf = henyeyGreensteinPdf(wiLocal.z, vertex.medium.g);
    path.previousDelta = false;
    recordScattering(path.history, false);
    path.ray = Ray(vertex.posWorld, normalize(toWorld(makeShadingFrame(path.ray.direction), wiLocal)));
    recordPhaseSample(bounce, path.ray.direction, path.previousPdf);
    path.bounce = bounce + 1;
    if (playsRoulette(bounce) && !survivesRoulette(path, sampler, bounce)) return false;
    recordThroughput(bounce, path.throughput);
    return true;
}

// The next vertex along path.ray: in scenes with media the free flight through them decides
// between a surface and a point in a medium (which scatterInMedium handles); else the nearest
// surface.
int findNextVertex(inout PathState path, Sampler sampler, out Hit hit, out MediumVertex scattering) {
    if (mediaInScene()) {
        recordSegmentStart(path.media);
        return flyToNextVertex(path.ray, path.media, path.throughput, samplerGet2D(sampler, freeFlightDimension(path.bounce)),
                               hit, scattering);
    }
    scattering = MediumVertex(vec3(0.0), Medium(vec3(0.0), vec3(0.0), 0.0));
    return intersectScene(path.ray, hit) ? kFlightSurface : kFlightEscaped;
}

// Follows the path one bounce: the surface the ray finds (or the point where a medium scatters
// it), its emission, next-event estimation and the BSDF sample that makes the next ray. Returns
// false once the path has ended, with its estimate in path.radiance.
bool extendPath(inout PathState path, Sampler sampler) {
    int bounce = path.bounce;
    Hit hit;
    MediumVertex scattering;
    int flight = findNextVertex(path, sampler, hit, scattering);
    if (flight == kFlightLost) return false;
    if (flight == kFlightScattered) return scatterInMedium(path, scattering, sampler);
    bool found = flight == kFlightSurface;
    recordSurface(bounce, found, hit, path.ray, path.throughput);
    if (!found) {
        if (countsEmissionFoundAt(bounce))
            addEmissionFound(path, environmentRadiance(path.ray.direction), uEnvironmentLight, kInfinity, vec3(0.0));
        return false;
    }

    Material material = fetchSurfaceMaterial(hit.material, hit.uv);
    if (countsEmissionFoundAt(bounce)) {
        vec3 emitted = emittedRadiance(material, hit.normalGeom, -path.ray.direction);
        if (any(greaterThan(emitted, vec3(0.0)))) addEmissionFound(path, emitted, hit.light, hit.t, hit.normalGeom);
    }
    if (bounce >= lastBounce() || material.type == kMaterialEmitter || path.emissionOnly) return false; // emitters reflect nothing

    ShadingFrame frame = makeShadingFrame(hit.normalShading); // BSDFs handle either side themselves
    vec3 woLocal = toLocal(frame, -path.ray.direction);
    if (samplesLights()) addDirectLighting(path, material, frame, hit, woLocal, sampler);
    if (!samplesBsdf()) return false;
    if (!scatter(path, material, frame, hit, woLocal, sampler)) return false;
    if (playsRoulette(bounce) && !survivesRoulette(path, sampler, bounce)) return false;
    recordThroughput(bounce, path.throughput);
    return true;
}

vec3 estimateRadiance(Ray ray, Sampler sampler) {
    PathState path = startPath(ray);
    while (extendPath(path, sampler)) {}
    return path.radiance;
}
