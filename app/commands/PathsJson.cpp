#include <ptview/commands/PathsJson.h>

#include <nlohmann/json.hpp>

#include <algorithm>

namespace ptview {
namespace {

using Json = nlohmann::ordered_json; // keys in the schema's order

Json vec(glm::vec3 v) { return Json::array({v.x, v.y, v.z}); }

int lastBounce(const RenderSettings& settings) {
    return settings.integrator == Integrator::Full || settings.integrator == Integrator::Naive ? settings.maxDepth
                                                                                              : std::min(settings.maxDepth, 1);
}

void addMaterial(Json& j, int material, const Scene& scene) {
    j["material"] = material;
    if (material >= 0 && static_cast<size_t>(material) < scene.materials.size())
        j["material_name"] = scene.materials[static_cast<size_t>(material)].name;
}

// withMedia: the scene has media, and every vertex says what they left of the light on the way
// (scenes without keep the fields they always had).
Json vertexJson(const PathVertex& v, size_t index, const Scene& scene, bool withMedia) {
    const bool medium = v.kind == PathVertex::Kind::Medium;
    Json j = Json::object();
    j["index"] = index;
    j["kind"] = pathVertexKindName(v.kind);
    if (v.kind != PathVertex::Kind::Escaped) j["position"] = vec(v.position);
    if (v.kind == PathVertex::Kind::Surface) {
        j["normal_geometric"] = vec(v.normalGeom);
        j["normal_shading"] = vec(v.normalShading);
        addMaterial(j, v.material, scene);
        j["surface_light"] = v.surfaceLight;
    }
    if (medium) {
        addMaterial(j, v.material, scene);
        j["sigma_t"] = vec(v.sigmaT);
        j["g"] = v.phaseG;
    }
    if (withMedia && v.kind != PathVertex::Kind::Camera) {
        j["segment_transmittance"] = vec(v.segmentTransmittance);
        j["transmittance_so_far"] = vec(v.transmittanceSoFar);
    }
    j["throughput_in"] = vec(v.throughputIn);
    j["throughput_out"] = vec(v.throughputOut);
    j["contribution"] = vec(v.contribution());
    if (v.emissionCounted)
        j["emission"] = Json{{"emitted", vec(v.emitted)},
                             {"mis_weight", v.emissionMisWeight},
                             {"bsdf_pdf", v.emissionBsdfPdf},
                             {"light_pdf", v.emissionLightPdf},
                             {"contribution", vec(v.emissionContribution)}};
    if (v.lightSampled) {
        Json light{{"light", v.sampledLight},
                   {v.lightAtInfinity ? "direction" : "point", vec(v.lightPoint)},
                   {"delta", v.lightDelta},
                   {"pdf", v.lightPdf},
                   {medium ? "phase_pdf" : "bsdf_pdf", v.lightBsdfPdf},
                   {"pdf_evaluated", v.lightPdfEvaluated},
                   {"shadow_ray", !v.shadowTraced ? "not_traced" : v.shadowBlocked ? "blocked" : "reached"}};
        if (v.shadowBlocked) light["blocked_at"] = v.shadowHitDistance;
        if (withMedia && v.shadowTraced) light["shadow_transmittance"] = vec(v.shadowTransmittance);
        if (v.shadowTraced && !v.shadowBlocked) light["mis_weight"] = v.lightMisWeight;
        light["contribution"] = vec(v.directContribution);
        j["light_sample"] = light;
    }
    if (v.kind == PathVertex::Kind::Escaped || v.kind == PathVertex::Kind::Camera) {
        j["direction"] = vec(v.direction);
    } else if (v.bsdfSampled && medium) {
        j["phase_sample"] = Json{{"direction", vec(v.direction)}, {"pdf", v.bsdfPdf}};
    } else if (v.bsdfSampled) {
        j["bsdf_sample"] = Json{{"direction", vec(v.direction)},
                                {"delta", v.bsdfDelta},
                                {"pdf", v.bsdfPdf},
                                {"pdf_evaluated", v.bsdfPdfEvaluated}};
    }
    if (v.roulette) j["roulette"] = Json{{"survival", v.survival}, {"ended", v.rouletteEnded}};
    return j;
}

} // namespace

bool pathsShowMedia(const Scene& scene) {
    return std::any_of(scene.materials.begin(), scene.materials.end(), [](const Material& m) { return m.boundsMedium(); });
}

const char* pathEnd(const RecordedPath& path, const RenderSettings& settings, const Scene& scene) {
    if (path.vertices.empty()) return "absorbed";
    const PathVertex& last = path.vertices.back();
    if (last.kind == PathVertex::Kind::Escaped) return "escaped";
    if (last.rouletteEnded) return "roulette";
    if (last.kind == PathVertex::Kind::Surface && last.material >= 0 &&
        static_cast<size_t>(last.material) < scene.materials.size() &&
        scene.materials[static_cast<size_t>(last.material)].type == MaterialType::Emitter)
        return "emitter";
    if (static_cast<int>(path.vertices.size()) - 2 == lastBounce(settings)) return "last_bounce";
    if (settings.integrator == Integrator::Direct && path.vertices.size() == 2) return "direct_only";
    return "absorbed";
}

std::string pathsToJson(const PathsReport& report) {
    const Scene& scene = *report.scene;
    const std::vector<RecordedPath>& paths = *report.paths;
    Json j = Json::object();
    j["ptview"] = "paths";
    j["version"] = 1;
    j["scene"] = report.scenePath;
    j["image_size"] = Json::array({report.imageSize.x, report.imageSize.y});
    j["pixel"] = Json::array({report.pixel.x, report.pixel.y});
    const RenderSettings& s = report.settings;
    j["settings"] = Json{{"integrator", integratorName(s.integrator)},
                         {"sampler", samplerModeName(s.sampler)},
                         {"depth", s.maxDepth},
                         {"seed", s.seed},
                         {"sample_budget", s.sampleBudget},
                         {"light_paths", lightPathsName(s.lightPaths)},
                         {"bounces", s.lightPathBounces},
                         {"clamp", s.radianceClamp ? Json(*s.radianceClamp) : Json(nullptr)}};
    j["first_sample"] = report.firstSample;
    j["count"] = paths.size();
    glm::vec3 mean(0.0f);
    for (const RecordedPath& path : paths) mean += path.summedContributions() / static_cast<float>(paths.size());
    j["mean"] = vec(mean);
    const bool withMedia = pathsShowMedia(scene);
    Json list = Json::array();
    for (const RecordedPath& path : paths) {
        Json p = Json::object();
        p["sample"] = path.sampleIndex;
        p["radiance"] = vec(path.radiance);
        p["end"] = pathEnd(path, s, scene);
        Json vertices = Json::array();
        for (size_t i = 0; i < path.vertices.size(); ++i) vertices.push_back(vertexJson(path.vertices[i], i, scene, withMedia));
        p["vertices"] = std::move(vertices);
        list.push_back(std::move(p));
    }
    j["paths"] = std::move(list);
    return j.dump(1) + "\n";
}

} // namespace ptview
