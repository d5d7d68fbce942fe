#include <ptview/session/PixelInspection.h>

#include <ptview/io/ImageIO.h>
#include <ptview/scene/ShapeSchema.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <stdexcept>

namespace ptview {
namespace {

nlohmann::ordered_json vectorJson(const glm::vec3& v) { return nlohmann::ordered_json::array({v.x, v.y, v.z}); }

std::string materialName(const Scene& scene, int material) {
    bool known = material >= 0 && material < static_cast<int>(scene.materials.size());
    return known ? scene.materials[static_cast<size_t>(material)].name : std::string();
}

nlohmann::ordered_json mediaJson(const CameraRayMedia& media, const Scene& scene) {
    nlohmann::ordered_json around = nlohmann::ordered_json::array();
    for (int material : media.around) around.push_back(materialName(scene, material));
    nlohmann::ordered_json crossed = nlohmann::ordered_json::array();
    for (const CameraRayMedia::Crossing& crossing : media.crossed)
        crossed.push_back({{"material", materialName(scene, crossing.material)}, {"distance", crossing.distance}});
    return {{"camera_in", around}, {"boundaries_crossed", media.crossings}, {"crossed", crossed}};
}

} // namespace

const char* finiteStatus(const glm::vec3& mean) {
    if (std::isnan(mean.x) || std::isnan(mean.y) || std::isnan(mean.z)) return "NaN";
    if (std::isinf(mean.x) || std::isinf(mean.y) || std::isinf(mean.z)) return "Inf";
    return "finite";
}

bool sameView(const CameraDesc& a, const CameraDesc& b) {
    return a.eye == b.eye && a.target == b.target && a.up == b.up && a.vfovDeg == b.vfovDeg;
}

std::string pixelInspectionJson(const PixelInspection& inspection, const Scene& scene) {
    const PixelReading& reading = inspection.reading;
    nlohmann::ordered_json out;
    out["pixel"] = {inspection.pixel.x, inspection.pixel.y};
    out["image_size"] = {inspection.imageSize.x, inspection.imageSize.y};
    out["side"] = !inspection.comparing ? "single" : inspection.rightSide ? "right" : "left";
    out["spp"] = reading.sampleCount;
    out["mean"] = vectorJson(reading.mean); // NaN and Inf are written as null; "status" says which
    out["standard_error"] = vectorJson(reading.standardError());
    out["status"] = finiteStatus(reading.mean);
    out["displayed_srgb8"] = {reading.displayed.x, reading.displayed.y, reading.displayed.z};
    if (inspection.denoised) { // only where the side shows the denoised image; "mean" stays the raw one
        out["denoised"] = vectorJson(*inspection.denoised);
        out["denoised_spp"] = inspection.denoisedSamples;
    }
    // "hit" is the surface the pixel showed when pinned; after a camera move the mean is not of it.
    out["camera_moved_since_pin"] = inspection.cameraMoved;
    if (!inspection.hit) {
        out["hit"] = nullptr; // the ray escapes to the environment
    } else {
        const SurfaceHit& hit = *inspection.hit;
        nlohmann::ordered_json h;
        h["distance"] = hit.distance;
        h["view_distance"] = hit.viewDistance;
        h["position"] = vectorJson(hit.position);
        h["normal_geometric"] = vectorJson(hit.normalGeom);
        h["normal_shading"] = vectorJson(hit.normalShading);
        h["uv"] = {hit.uv.x, hit.uv.y};
        h["material_index"] = hit.material;
        h["material"] = materialName(scene, hit.material);
        h["shape_index"] = hit.shape;
        bool knownShape = hit.shape >= 0 && hit.shape < static_cast<int>(scene.shapes.size());
        h["shape"] = knownShape ? scene.shapes[static_cast<size_t>(hit.shape)].name : std::string();
        h["shape_type"] = knownShape ? shapeSchema(scene.shapes[static_cast<size_t>(hit.shape)].type).name : "";
        out["hit"] = h;
    }
    // Only where there is a medium to name: the files of scenes without media stay as they were.
    if (!inspection.media.empty()) out["media"] = mediaJson(inspection.media, scene);
    return out.dump(2) + "\n";
}

void savePixelInspection(const PixelInspection& inspection, const Scene& scene, const std::filesystem::path& path) {
    writeFileAtomically(path, pixelInspectionJson(inspection, scene));
}

} // namespace ptview
