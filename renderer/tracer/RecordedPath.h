#pragma once
// The paths behind a pixel, as the GPU traced them (renderer/tracer/PathRecorder.*): plain values, no
// OpenGL, so that the JSON writer, the picture and the viewer's table read them as they are.
// Directions are world space and unit; pdfs are solid-angle densities; a light pdf includes the
// probability of choosing that light. Vertex 0 is the camera; vertex k + 1 is what the ray of
// bounce k found: a surface, a point where a medium scattered it (a bounce like a surface's, its
// phase function in the BSDF's place), or the environment (escaped).

#include <glm/glm.hpp>

#include <vector>

namespace ptview {

struct PathVertex {
    enum class Kind { Camera, Surface, Medium, Escaped };
    Kind kind = Kind::Camera;
    glm::vec3 position{0.0f};       // camera, surface and medium; for an escaped vertex, see `direction`
    glm::vec3 normalGeom{0.0f};     // surface only
    glm::vec3 normalShading{0.0f};
    int material = -1;              // index into the scene's materials, -1: none (a medium's point: the medium's)
    int surfaceLight = -1;          // light index of the emitting surface hit, -1: none

    // Where a medium scattered the path (Kind::Medium): its coefficients.
    glm::vec3 sigmaT{0.0f};         // extinction, sigma_a + sigma_s, per metre
    float phaseG = 0.0f;            // Henyey-Greenstein asymmetry

    // Media on the way (all 1 in scenes without media).
    glm::vec3 segmentTransmittance{1.0f};  // of the segment that reached this vertex
    glm::vec3 transmittanceSoFar{1.0f};    // of all the segments from the camera to here
    glm::vec3 shadowTransmittance{1.0f};   // of the light sample's shadow ray

    glm::vec3 throughputIn{0.0f};   // the path's weight arriving here
    glm::vec3 throughputOut{0.0f};  // leaving (sample weight and roulette applied); 0 where the path ends

    // The BSDF sample taken here (continues the path); at a medium's point the phase function's.
    bool bsdfSampled = false;       // a sample of nonzero pdf was drawn
    bool bsdfDelta = false;         // from a delta lobe (mirror, glass): no density to weigh against
    float bsdfPdf = 0.0f;           // its density as sampled
    float bsdfPdfEvaluated = 0.0f;  // bsdfPdf() of the same direction (0 for a delta lobe)
    glm::vec3 direction{0.0f};      // of the ray leaving (the camera ray at vertex 0; the escape
                                    // direction at an escaped vertex)
    bool continued = false;         // a ray left this vertex

    // Russian roulette after this vertex's sample.
    bool roulette = false;
    float survival = 0.0f;
    bool rouletteEnded = false;

    // Next-event estimation: one light sample and its shadow ray.
    bool lightSampled = false;      // a sample of nonzero pdf and radiance was drawn
    int sampledLight = -1;
    bool lightDelta = false;        // point, spot or directional: only light sampling finds it
    bool lightAtInfinity = false;   // environment or directional: lightPoint holds a direction
    glm::vec3 lightPoint{0.0f};
    bool shadowTraced = false;      // the BSDF and the sides allowed the sample, so its ray was cast
    bool shadowBlocked = false;
    float shadowHitDistance = -1.0f; // to the first surface on the shadow ray's line (the blocker), -1: none
    float lightPdf = 0.0f;          // as sampled
    float lightBsdfPdf = 0.0f;      // bsdfPdf() of the sample's direction
    float lightMisWeight = 0.0f;    // weight of the light-sampling strategy (1 without MIS)
    float lightPdfEvaluated = -1.0f; // the light pdf of that direction as a BSDF sample finding the
                                    // light is weighed (-1: the shadow ray does not reach the light)
    glm::vec3 directContribution{0.0f}; // added to the pixel by the light sample

    // Emission the ray arriving here found (a light, an emitting surface, the environment).
    bool emissionCounted = false;
    glm::vec3 emitted{0.0f};
    float emissionMisWeight = 0.0f;   // weight of the BSDF-sampling strategy (1: nothing else finds it)
    float emissionBsdfPdf = 0.0f;     // density of the BSDF sample that arrived (0: the camera ray)
    float emissionLightPdf = 0.0f;    // light pdf of that direction from the previous vertex
    glm::vec3 emissionContribution{0.0f};

    glm::vec3 contribution() const { return directContribution + emissionContribution; }
};

// How the recording pass hands a vertex over: kRecordFields vec4 (shaders/path_recorder.glsl says
// what each holds), field 0's w holding these flags as a float of exact integer value. The GLSL
// gets both from here, as the generated include "recorded_path.glsl" (PathRecorder.h).
constexpr int kRecordFields = 14;

enum VertexFlag : unsigned {
    kVertexExists = 1u,
    kVertexCamera = 2u,
    kVertexSurface = 4u,
    kVertexEmission = 8u,
    kVertexLightSampled = 16u,
    kVertexShadowTraced = 32u,
    kVertexShadowBlocked = 64u,
    kVertexLightDelta = 128u,
    kVertexLightAtInfinity = 256u,
    kVertexBsdfSampled = 512u,
    kVertexBsdfDelta = 1024u,
    kVertexRoulette = 2048u,
    kVertexRouletteEnded = 4096u,
    kVertexContinued = 8192u,
    kVertexMedium = 16384u,
};

// Each flag's GLSL name and meaning, for the generated include.
struct VertexFlagName {
    VertexFlag flag;
    const char* name;
    const char* meaning;
};
inline constexpr VertexFlagName kVertexFlagNames[] = {
    {kVertexExists, "kVertexExists", ""},
    {kVertexCamera, "kVertexCamera", ""},
    {kVertexSurface, "kVertexSurface", "else, when it exists and is not the camera, it escaped"},
    {kVertexEmission, "kVertexEmission", "emission found here was counted (field 8 w, 9, 10)"},
    {kVertexLightSampled, "kVertexLightSampled", "a light sample of nonzero pdf and radiance was drawn"},
    {kVertexShadowTraced, "kVertexShadowTraced", "... and its shadow ray traced (f and sides allowed it)"},
    {kVertexShadowBlocked, "kVertexShadowBlocked", ""},
    {kVertexLightDelta, "kVertexLightDelta", "the sampled light is a point, spot or directional light"},
    {kVertexLightAtInfinity, "kVertexLightAtInfinity", ""},
    {kVertexBsdfSampled, "kVertexBsdfSampled", "a BSDF sample of nonzero pdf was drawn"},
    {kVertexBsdfDelta, "kVertexBsdfDelta", ""},
    {kVertexRoulette, "kVertexRoulette", "roulette was played after this vertex's sample"},
    {kVertexRouletteEnded, "kVertexRouletteEnded", ""},
    {kVertexContinued, "kVertexContinued", "a ray left this vertex"},
    {kVertexMedium, "kVertexMedium", "a medium scattered the path here (field 1: sigma_t, the medium; 12 w: g)"},
};

// The name of a vertex's kind, as `ptview paths` writes it and the viewer's paths table shows it.
inline const char* pathVertexKindName(PathVertex::Kind kind) {
    switch (kind) {
    case PathVertex::Kind::Camera: return "camera";
    case PathVertex::Kind::Surface: return "surface";
    case PathVertex::Kind::Medium: return "medium";
    case PathVertex::Kind::Escaped: return "escaped";
    }
    return "?";
}

struct RecordedPath {
    int sampleIndex = 0;      // the render's sample (frame) index this path is
    glm::vec3 radiance{0.0f}; // what the integrator returned for it: the sum of the contributions
    std::vector<PathVertex> vertices;

    glm::vec3 summedContributions() const {
        glm::vec3 sum(0.0f);
        for (const PathVertex& vertex : vertices) { // in the integrator's order: emission, then the light sample
            sum += vertex.emissionContribution;
            sum += vertex.directContribution;
        }
        return sum;
    }
};

} // namespace ptview
