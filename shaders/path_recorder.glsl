// The path recorder's hooks (renderer/tracer/PathRecorder.*, shaders/path_record.frag): the integrator
// calls them where it knows a quantity, and one fragment of the recording pass keeps what they
// report for one vertex of one path (gRecordVertex): vertex 0 is the camera, vertex b + 1 what
// the ray of bounce b found. Every fragment traces the whole path again, because GL 4.1 fragments
// have nowhere else to write a list to; the cost is paths x vertices, nothing for a few paths.
// The hooks are statements beside the maths and change nothing of it, so the path traced and the
// sum added are the render's. Only the recording program includes this file; path_recorder_none.glsl takes
// its place in every other.
//
// The record of a vertex is 12 vec4 (kRecordFields), the layout renderer/tracer/PathRecorder.cpp reads:
//   0  position (an escaped vertex: the direction it left in), flags (kVertex* bits)
//   1  geometric normal, material index (-1: none)
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
//      shadow ray's line meets (where a blocked one stops; -1: none)
// kRecordFields and the kVertex* flags: generated from renderer/tracer/RecordedPath.h.
#include "recorded_path.glsl"

int gRecordVertex;              // the vertex this fragment keeps
vec4 gRecord[kRecordFields];    // what the hooks reported for it
uint gFlags;
vec3 gPreviousPos;              // where the ray being traced started (unpushed), for its light pdf
float gPreviousBsdfPdf;         // density of the BSDF sample that made it (0: the camera ray)

void startRecording(int vertex, Ray cameraRay) {
    gRecordVertex = vertex;
    for (int i = 0; i < kRecordFields; ++i) gRecord[i] = vec4(0.0);
    gRecord[1].w = -1.0;
    gRecord[2].w = -1.0;
    gRecord[6].w = -1.0;
    gFlags = 0u;
    gPreviousPos = cameraRay.origin;
    gPreviousBsdfPdf = 0.0;
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

void recordSurface(int bounce, bool found, Hit hit, Ray ray, vec3 throughput) {
    if (isRecorded(bounce)) {
        gFlags |= kVertexExists | (found ? kVertexSurface : 0u);
        gRecord[0].xyz = found ? hit.posWorld : ray.direction;
        gRecord[3].xyz = throughput;
        gRecord[10].w = gPreviousBsdfPdf;
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

void recordLightSample(int bounce, int light, float selection, LightSample ls, Material material, ShadingFrame frame,
                       vec3 woLocal, Hit hit) {
    if (!isRecorded(bounce)) return;
    bool atInfinity = ls.distance >= kInfinity;
    if (ls.pdfSolidAngle > 0.0 && selection > 0.0 && any(greaterThan(ls.radiance, vec3(0.0)))) gFlags |= kVertexLightSampled;
    if (ls.isDelta) gFlags |= kVertexLightDelta;
    if (atInfinity) gFlags |= kVertexLightAtInfinity;
    gRecord[6] = vec4(atInfinity ? ls.wi : hit.posWorld + ls.distance * ls.wi, float(light));
    gRecord[7].x = selection * ls.pdfSolidAngle;
    gRecord[7].y = bsdfPdf(material, woLocal, toLocal(frame, ls.wi));
    // The density BSDF-found emission would be weighed with, from the light's own surface as the
    // shadow ray's direction meets it: equal to the sample's pdf when the two strategies agree.
    Hit first;
    bool hitSomething = intersectScene(spawnRay(hit.posWorld, hit.normalGeom, ls.wi), first);
    gRecord[11].w = hitSomething ? first.t : -1.0;
    float evaluated = -1.0;
    if (ls.isDelta) evaluated = 0.0;
    else if (atInfinity) evaluated = recordedLightPdf(light, hit.posWorld, ls.wi, kInfinity, vec3(0.0));
    else if (hitSomething && first.light == light) evaluated = recordedLightPdf(light, hit.posWorld, ls.wi, first.t, first.normalGeom);
    gRecord[7].w = evaluated;
}

void recordShadowRay(int bounce, bool blocked) {
    if (isRecorded(bounce)) gFlags |= kVertexShadowTraced | (blocked ? kVertexShadowBlocked : 0u);
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
