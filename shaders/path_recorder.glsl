// The path recorder's hooks (renderer/tracer/PathRecorder.*, shaders/path_record.frag): the integrator
// calls them where it knows a quantity, and one fragment of the recording pass keeps what they
// report for one vertex of one path (gRecordVertex): vertex 0 is the camera, vertex b + 1 what
// the ray of bounce b found. Every fragment traces the whole path again, because GL 4.1 fragments
// have nowhere else to write a list to; the cost is paths x vertices, nothing for a few paths.
// The hooks are statements beside the maths and change nothing of it, so the path traced and the
// sum added are the render's. Only the recording program includes this file; path_recorder_none.glsl takes
// its place in every other.
//
// The record of a vertex is 14 vec4 (kRecordFields), the layout renderer/tracer/PathRecorder.cpp reads.
// At a point where a medium scattered the path (kVertexMedium), the phase function stands for the
// BSDF: its sample is the "BSDF sample", its density the "bsdfPdf".
//   0  position (an escaped vertex: the direction it left in), flags (kVertex* bits)
//   1  geometric normal (a medium's point: the medium's sigma_t = sigma_a + sigma_s, per metre),
//      material index (-1: none; a medium's point: the medium's material)
//   2  shading normal, light index of the surface hit (-1: none)
//   3  throughput arriving here, solid-angle pdf of the BSDF sample taken here
//   4  throughput leaving (after the sample's weight and roulette; 0 where the path ends),
//      bsdfPdf evaluated for that sampled direction (what MIS against light sampling uses)
//   5  direction of the ray leaving (world), roulette survival probability (0: no roulette here)
//   6  light sample: point on the light (at infinity: its direction), light index (-1: none)
//   7  light sample: pdf (selection x solid angle), bsdfPdf of its direction, its MIS weight,
//      the light pdf of that direction evaluated as emission found by a BSDF sample would be
//      (selection x lightPdf; -1 when the shadow ray does not reach the light)
//   8  contribution added by the light sample (after clamp and light-path view), MIS weight of the
//      emission found here
//   9  contribution added by emission found here (environment included), light pdf of the
//      direction that found it (selection x lightPdf, from the previous vertex; 0: not a light)
//  10  emitted radiance found here, pdf of the BSDF sample that found it (0 for the camera ray)
//  11  the path's radiance (what estimateRadiance returned), distance to the first surface the
//      shadow ray's line meets, null boundaries aside (where a blocked one stops; -1: none)
//  12  transmittance of the segment that reached this vertex (1 without media), a medium's
//      Henyey-Greenstein asymmetry g
//  13  transmittance of the light sample's shadow ray (1 without media), unused
// kRecordFields and the kVertex* flags: generated from renderer/tracer/RecordedPath.h.
#include "recorded_path.glsl"

int gRecordVertex;              // the vertex this fragment keeps
vec4 gRecord[kRecordFields];    // what the hooks reported for it
uint gFlags;
vec3 gPreviousPos;              // where the ray being traced started (unpushed), for its light pdf
float gPreviousBsdfPdf;         // density of the BSDF sample that made it (0: the camera ray)
MediumStack gSegmentMedia;      // the media the ray being traced started in

void startRecording(int vertex, Ray cameraRay) {
    gRecordVertex = vertex;
    for (int i = 0; i < kRecordFields; ++i) gRecord[i] = vec4(0.0);
    gRecord[1].w = -1.0;
    gRecord[2].w = -1.0;
    gRecord[6].w = -1.0;
    gRecord[12].xyz = vec3(1.0);
    gRecord[13].xyz = vec3(1.0);
    gFlags = 0u;
    gPreviousPos = cameraRay.origin;
    gPreviousBsdfPdf = 0.0;
    gSegmentMedia = cameraMediumStack();
    if (vertex == 0) {
        gFlags = kVertexExists | kVertexCamera | kVertexContinued;
        gRecord[0].xyz = cameraRay.origin;
        gRecord[3].xyz = vec3(1.0);
        gRecord[4].xyz = vec3(1.0);
        gRecord[5].xyz = cameraRay.direction;
    }
}

bool isRecorded(int bounce) { return bounce + 1 == gRecordVertex; }

// Selection x solid-angle density of `light` producing direction wi from pos, the light's point
// at distance t with normal n: what emissionWeight weighs a BSDF sample against.
float recordedLightPdf(int light, vec3 pos, vec3 wi, float t, vec3 n) {
    return light < 0 ? 0.0 : lightSelectionProbability(light) * lightPdf(light, pos, wi, t, n);
}

// What the media keep of the light along the segment the path just flew, from ray.origin to the
// point `distance` along ray (kInfinity: it escaped), through the media it started in: a shadow
// ray's transmittance, stopped a hair short of a surface at the end, which would block it.
vec3 recordedSegmentTransmittance(Ray ray, float distance, bool endsOnSurface) {
    if (!mediaInScene()) return vec3(1.0);
    return shadowTransmittance(ray, endsOnSurface ? distance * (1.0 - 1e-5) : distance, -1, gSegmentMedia);
}

// A ray is about to fly from a vertex through `media` (in scenes with media).
void recordSegmentStart(MediumStack media) { gSegmentMedia = media; }

void recordSurface(int bounce, bool found, Hit hit, Ray ray, vec3 throughput) {
    if (isRecorded(bounce)) {
        gFlags |= kVertexExists | (found ? kVertexSurface : 0u);
        gRecord[0].xyz = found ? hit.posWorld : ray.direction;
        gRecord[3].xyz = throughput;
        gRecord[10].w = gPreviousBsdfPdf;
        gRecord[12].xyz = recordedSegmentTransmittance(ray, found ? hit.t : kInfinity, found);
        if (found) {
            gRecord[1] = vec4(hit.normalGeom, float(hit.material));
            gRecord[2] = vec4(hit.normalShading, float(hit.light));
            gRecord[9].w = recordedLightPdf(hit.light, gPreviousPos, ray.direction, hit.t, hit.normalGeom);
        } else {
            gRecord[9].w = recordedLightPdf(uEnvironmentLight, gPreviousPos, ray.direction, kInfinity, vec3(0.0));
        }
    }
    if (found) gPreviousPos = hit.posWorld;
}

void recordEmissionWeight(int bounce, float misWeight, vec3 emitted) {
    if (isRecorded(bounce)) {
        gFlags |= kVertexEmission;
        gRecord[8].w = misWeight;
        gRecord[10].xyz = emitted;
    }
}

void recordEmission(int bounce, vec3 added) {
    if (isRecorded(bounce)) gRecord[9].xyz = added;
}

// A light sample drawn from posWorld, the shadow ray's line being shadowLine; scatteringPdf is the
// density of the sample's direction for the BSDF (or phase function) there.
void recordLightSampleFrom(vec3 posWorld, Ray shadowLine, int light, float selection, LightSample ls, float scatteringPdf) {
    bool atInfinity = ls.distance >= kInfinity;
    if (ls.pdfSolidAngle > 0.0 && selection > 0.0 && any(greaterThan(ls.radiance, vec3(0.0)))) gFlags |= kVertexLightSampled;
    if (ls.isDelta) gFlags |= kVertexLightDelta;
    if (atInfinity) gFlags |= kVertexLightAtInfinity;
    gRecord[6] = vec4(atInfinity ? ls.wi : posWorld + ls.distance * ls.wi, float(light));
    gRecord[7].x = selection * ls.pdfSolidAngle;
    gRecord[7].y = scatteringPdf;
    // The density BSDF-found emission would be weighed with, from the light's own surface as the
    // shadow ray's direction meets it: equal to the sample's pdf when the two strategies agree.
    // Media's null boundaries let the ray through, so they neither block nor emit.
    Hit first;
    bool hitSomething = intersectSurface(shadowLine, first);
    gRecord[11].w = hitSomething ? first.t : -1.0;
    float evaluated = -1.0;
    if (ls.isDelta) evaluated = 0.0;
    else if (atInfinity) evaluated = recordedLightPdf(light, posWorld, ls.wi, kInfinity, vec3(0.0));
    else if (hitSomething && first.light == light) evaluated = recordedLightPdf(light, posWorld, ls.wi, first.t, first.normalGeom);
    gRecord[7].w = evaluated;
}

void recordLightSample(int bounce, int light, float selection, LightSample ls, Material material, ShadingFrame frame,
                       vec3 woLocal, Hit hit) {
    if (isRecorded(bounce))
        recordLightSampleFrom(hit.posWorld, spawnRay(hit.posWorld, hit.normalGeom, ls.wi), light, selection, ls,
                              bsdfPdf(material, woLocal, toLocal(frame, ls.wi)));
}

// transmittance: what media leave of the light along the shadow ray (1 without).
void recordShadowRay(int bounce, bool blocked, vec3 transmittance) {
    if (isRecorded(bounce)) {
        gFlags |= kVertexShadowTraced | (blocked ? kVertexShadowBlocked : 0u);
        gRecord[13].xyz = transmittance;
    }
}

void recordLightWeight(int bounce, float misWeight) {
    if (isRecorded(bounce)) gRecord[7].z = misWeight;
}

void recordDirectLighting(int bounce, vec3 added) {
    if (isRecorded(bounce)) gRecord[8].xyz = added;
}

void recordBsdfSample(int bounce, BsdfSample bs, Material material, ShadingFrame frame, vec3 woLocal) {
    if (isRecorded(bounce)) {
        if (bs.pdfSolidAngle > 0.0) gFlags |= kVertexBsdfSampled;
        if (bs.isDelta) gFlags |= kVertexBsdfDelta;
        gRecord[3].w = bs.pdfSolidAngle;
        gRecord[4].w = bs.isDelta ? 0.0 : bsdfPdf(material, woLocal, bs.wiLocal);
        gRecord[5].xyz = toWorld(frame, bs.wiLocal);
    }
    gPreviousBsdfPdf = bs.pdfSolidAngle;
}

void recordRoulette(int bounce, float survival, bool ended) {
    if (isRecorded(bounce)) {
        gFlags |= kVertexRoulette | (ended ? kVertexRouletteEnded : 0u);
        gRecord[5].w = survival;
    }
}

void recordThroughput(int bounce, vec3 throughput) {
    if (isRecorded(bounce)) {
        gFlags |= kVertexContinued;
        gRecord[4].xyz = throughput;
    }
}

// ---- Where a medium scattered the path (shaders/integrator.glsl, scatterInMedium) -------------

// The path reached vertex.posWorld along ray, in `media` (innermost last: the one that scattered).
void recordMediumScattering(int bounce, MediumVertex vertex, MediumStack media, Ray ray, vec3 throughput) {
    if (isRecorded(bounce)) {
        gFlags |= kVertexExists | kVertexMedium;
        gRecord[0].xyz = vertex.posWorld;
        gRecord[1] = vec4(vertex.medium.sigmaA + vertex.medium.sigmaS, float(media.materials[media.depth - 1]));
        gRecord[3].xyz = throughput;
        gRecord[10].w = gPreviousBsdfPdf;
        gRecord[12] = vec4(recordedSegmentTransmittance(ray, distance(ray.origin, vertex.posWorld), false), vertex.medium.g);
    }
    gPreviousPos = vertex.posWorld;
}

// directionIn: the direction the path arrived in (the phase function's is measured from it).
void recordMediumLightSample(int bounce, int light, float selection, LightSample ls, MediumVertex vertex,
                             vec3 directionIn) {
    if (isRecorded(bounce))
        recordLightSampleFrom(vertex.posWorld, Ray(vertex.posWorld, ls.wi), light, selection, ls,
                              henyeyGreensteinPdf(dot(directionIn, ls.wi), vertex.medium.g));
}

// The phase function's sample: its direction and solid-angle density (its weight is 1).
void recordPhaseSample(int bounce, vec3 wiWorld, float pdf) {
    if (isRecorded(bounce)) {
        if (pdf > 0.0) gFlags |= kVertexBsdfSampled;
        gRecord[3].w = pdf;
        gRecord[4].w = pdf;
        gRecord[5].xyz = wiWorld;
    }
    gPreviousBsdfPdf = pdf;
}
