#include <ptview/model/EditHistory.h>

#include <ptview/model/CameraController.h>
#include <ptview/model/SceneMerge.h>
#include <ptview/model/ViewerModel.h>
#include <ptview/scene/MaterialInputs.h>
#include <ptview/scene/MaterialSchema.h>
#include <ptview/scene/MaterialTextures.h>
#include <ptview/scene/MediumBoundaries.h>
#include <ptview/scene/SceneRanges.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

namespace ptview {
namespace {

// Exact, as sameMaterial: every value is a copy of one typed, dragged or read.
bool sameCamera(const CameraDesc& a, const CameraDesc& b) {
    return a.eye == b.eye && a.target == b.target && a.up == b.up && a.vfovDeg == b.vfovDeg && a.resolution == b.resolution &&
           a.apertureRadius == b.apertureRadius && a.focusDistance == b.focusDistance;
}

// The image is compared by identity: the panel and the script decode a file into a new one.
bool sameTexture(const SceneTexture& a, const SceneTexture& b) {
    return a.source == b.source && a.file == b.file && a.colorSpace == b.colorSpace && a.wrapU == b.wrapU &&
           a.wrapV == b.wrapV && a.bilinear == b.bilinear && a.image == b.image;
}

bool sameSlot(const TextureSlot& a, const TextureSlot& b) {
    return a.texture == b.texture && a.scale == b.scale && a.offset == b.offset;
}

template <typename T, typename Same>
bool sameList(const std::vector<T>& a, const std::vector<T>& b, Same same) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), same);
}

// The parts of a snapshot, as both a SceneEdits and a Scene hold them.
template <typename A, typename B>
bool sameEnvironment(const A& a, const B& b) {
    return a.environment == b.environment && a.environmentMap == b.environmentMap &&
           a.environmentIntensity == b.environmentIntensity && a.environmentRotationDeg == b.environmentRotationDeg;
}

template <typename A, typename B>
bool sameParts(const A& a, const B& b) {
    return sameCamera(a.camera, b.camera) && sameEnvironment(a, b) && sameList(a.materials, b.materials, sameMaterial) &&
           sameList(a.textures, b.textures, sameTexture) && sameList(a.lights, b.lights, sameLight);
}

// Whether only material parameters changed: the same materials (by count) with the same texture
// slots, over the same textures. A slot or a texture of its own needs the scene uploaded again.
bool sameTextureUse(const SceneEdits& a, const SceneEdits& b) {
    if (a.materials.size() != b.materials.size() || !sameList(a.textures, b.textures, sameTexture)) return false;
    for (std::size_t i = 0; i < a.materials.size(); ++i)
        for (const MaterialTextureInput& input : kMaterialTextureInputs)
            if (!sameSlot(a.materials[i].*input.slot, b.materials[i].*input.slot)) return false;
    return true;
}

// "a", "a and b", "a, b and c".
std::string joinedWithAnd(const std::vector<std::string>& parts) {
    std::string text;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        if (i > 0) text += i + 1 == parts.size() ? " and " : ", ";
        text += parts[i];
    }
    return text;
}

std::string withSpaces(std::string name) {
    std::replace(name.begin(), name.end(), '_', ' ');
    std::replace(name.begin(), name.end(), '-', ' ');
    return name;
}

// The fields of a material that differ, by the names the panel and the script use.
std::vector<std::string> materialChanges(const Material& a, const Material& b) {
    if (a.type != b.type) return {"type"}; // a type change moves the other fields with it
    std::vector<std::string> fields;
    const MaterialSchema& schema = materialSchema(b.type);
    if (a.color != b.color) fields.push_back(schema.colorKey ? withSpaces(schema.colorKey) : "colour");
    if (a.radiance != b.radiance) fields.push_back(b.type == MaterialType::Emitter ? "radiance" : "emission");
    for (const MaterialInput& input : kMaterialInputs)
        if (input.value == InputValue::Number && input.takenBy(schema) && a.*input.number != b.*input.number)
            fields.push_back(input.panelLabel ? input.panelLabel : withSpaces(input.key));
    if (a.alphaMode != b.alphaMode) fields.emplace_back("alpha mode");
    if (a.hasInterior != b.hasInterior) fields.emplace_back("interior");
    if (a.sigmaA != b.sigmaA) fields.emplace_back("absorption");
    if (a.sigmaS != b.sigmaS) fields.emplace_back("scattering");
    if (a.g != b.g && b.type != MaterialType::Medium) fields.emplace_back("g"); // a medium's is a Number input above
    for (const MaterialTextureInput& input : kMaterialTextureInputs)
        if (!sameSlot(a.*input.slot, b.*input.slot)) fields.push_back(withSpaces(input.name) + " texture");
    return fields;
}

std::vector<std::string> lightChanges(const Light& a, const Light& b) {
    std::vector<std::string> fields;
    if (a.intensity != b.intensity) fields.emplace_back("intensity");
    if (a.position != b.position) fields.emplace_back("position");
    if (a.direction != b.direction) fields.emplace_back("direction");
    if (a.innerAngleDeg != b.innerAngleDeg) fields.emplace_back("inner angle");
    if (a.outerAngleDeg != b.outerAngleDeg) fields.emplace_back("outer angle");
    return fields;
}

// "roughness of 'floor'" for one or two fields of one item, "material 'floor'" for more, "3
// materials" for several items. `noun` names the kind ("material", "light").
template <typename T, typename Changes>
void describeItems(const std::vector<T>& before, const std::vector<T>& after, Changes changes, const char* noun,
                   const char* ownNoun, std::vector<std::string>& parts) {
    if (before.size() != after.size()) {
        parts.push_back(std::string(noun) + "s");
        return;
    }
    std::vector<std::size_t> changed;
    for (std::size_t i = 0; i < after.size(); ++i)
        if (!changes(before[i], after[i]).empty() || before[i].name != after[i].name) changed.push_back(i);
    if (changed.empty()) return;
    if (changed.size() > 1) {
        parts.push_back(std::to_string(changed.size()) + " " + noun + "s");
        return;
    }
    const T& item = after[changed[0]];
    std::vector<std::string> fields = changes(before[changed[0]], item);
    std::string name = ownNoun + std::string("'") + item.name + "'";
    parts.push_back(fields.empty() || fields.size() > 2 ? std::string(noun) + " '" + item.name + "'"
                                                         : joinedWithAnd(fields) + " of " + name);
}

std::string numberText(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

// The range's problem with a value, or empty.
std::string outOfRange(const SceneRange& range, double value, const std::string& what) {
    if (range.contains(value)) return {};
    return what + " " + numberText(value) + " is not " + range.text();
}

std::string vectorOutOfRange(const SceneRange& range, const glm::vec3& value, const std::string& what) {
    for (int i = 0; i < 3; ++i)
        if (std::string problem = outOfRange(range, value[i], what); !problem.empty()) return problem;
    return {};
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The loader's rule for a camera's up (SceneFileReaders.cpp, areParallel).
bool parallel(const glm::vec3& a, const glm::vec3& b) {
    return glm::length(glm::cross(a, b)) <= 1e-6f * glm::length(a) * glm::length(b);
}

std::string cameraEditsProblem(const CameraDesc& camera) {
    if (std::string problem = cameraProblem(camera); !problem.empty()) return "camera: " + problem;
    if (!finite(camera.up) || camera.up == glm::vec3(0.0f) || parallel(camera.up, camera.target - camera.eye))
        return "camera: up is parallel to the view direction";
    if (std::string p = outOfRange(ranges::kApertureRadius, camera.apertureRadius, "camera: aperture radius"); !p.empty()) return p;
    return outOfRange(ranges::kFocusDistance, camera.focusDistance, "camera: focus distance");
}

std::string materialProblem(const Material& material, std::size_t textures) {
    const MaterialSchema& schema = materialSchema(material.type);
    const std::string what = "material '" + material.name + "': ";
    for (const MaterialInput& input : kMaterialInputs) {
        if (!input.takenBy(schema) || !input.range) continue;
        std::string problem;
        if (input.value == InputValue::Vector)
            problem = vectorOutOfRange(*input.range, material.*input.vector, what + input.range->quantity);
        else if (input.value == InputValue::Number)
            problem = outOfRange(*input.range, material.*input.number, what + input.range->quantity);
        if (!problem.empty()) return problem;
    }
    if (material.hasInterior) {
        const std::string interior = what + "interior ";
        if (std::string p = vectorOutOfRange(ranges::kMediumCoefficient, material.sigmaA, interior + "sigma_a"); !p.empty()) return p;
        if (std::string p = vectorOutOfRange(ranges::kMediumCoefficient, material.sigmaS, interior + "sigma_s"); !p.empty()) return p;
        if (std::string p = outOfRange(ranges::kPhaseAsymmetry, material.g, interior + "g"); !p.empty()) return p;
    }
    for (const MaterialTextureInput& input : kMaterialTextureInputs) {
        const TextureSlot& slot = material.*input.slot;
        if (slot.used() && static_cast<std::size_t>(slot.texture) >= textures)
            return what + input.name + " texture names no texture of the scene";
    }
    return {};
}

std::string lightProblem(const Light& light) {
    const std::string what = "light '" + light.name + "': ";
    if (std::string p = vectorOutOfRange(ranges::kIntensity, light.intensity, what + "intensity"); !p.empty()) return p;
    if (light.type != LightType::Directional)
        if (std::string p = vectorOutOfRange(ranges::kCoordinate, light.position, what + "position"); !p.empty()) return p;
    if (light.type != LightType::Point && (!finite(light.direction) || light.direction == glm::vec3(0.0f)))
        return what + "direction has no direction";
    if (light.type == LightType::Spot) {
        for (auto [angle, name] : {std::pair{light.innerAngleDeg, "inner angle"}, std::pair{light.outerAngleDeg, "outer angle"}})
            if (std::string p = outOfRange(ranges::kSpotConeAngle, angle, what + name); !p.empty()) return p;
        if (!ranges::coneAnglesOrdered(light.innerAngleDeg, light.outerAngleDeg))
            return what + "inner angle exceeds the outer angle";
    }
    return {};
}

} // namespace

SceneEdits SceneEdits::of(const Scene& scene, std::shared_ptr<const EnvironmentMap> map) {
    SceneEdits edits;
    edits.camera = scene.camera;
    edits.environment = scene.environment;
    edits.environmentMap = scene.environmentMap;
    edits.environmentIntensity = scene.environmentIntensity;
    edits.environmentRotationDeg = scene.environmentRotationDeg;
    edits.materials = scene.materials;
    edits.textures = scene.textures;
    edits.lights = scene.lights;
    edits.environmentMapData = std::move(map);
    return edits;
}

void SceneEdits::applyTo(Scene& scene) const {
    scene.camera = camera;
    scene.environment = environment;
    scene.environmentMap = environmentMap;
    scene.environmentIntensity = environmentIntensity;
    scene.environmentRotationDeg = environmentRotationDeg;
    scene.materials = materials;
    scene.textures = textures;
    scene.lights = lights;
}

Scene SceneEdits::toScene() const {
    Scene scene;
    applyTo(scene);
    return scene;
}

bool sameEdits(const SceneEdits& a, const SceneEdits& b) { return sameParts(a, b); }
bool sameEdits(const SceneEdits& edits, const Scene& scene) { return sameParts(edits, scene); }

unsigned changesBetween(const SceneEdits& from, const SceneEdits& to) {
    unsigned changes = 0;
    if (!sameCamera(from.camera, to.camera)) changes |= ViewerModel::kCameraChanged;
    if (!sameEnvironment(from, to) || !sameList(from.lights, to.lights, sameLight) || !sameTextureUse(from, to))
        changes |= ViewerModel::kSceneChanged;
    else if (!sameList(from.materials, to.materials, sameMaterial))
        changes |= ViewerModel::kMaterialsChanged;
    return changes;
}

std::string describeEdit(const SceneEdits& before, const SceneEdits& after) {
    std::vector<std::string> parts;
    describeItems(before.materials, after.materials, materialChanges, "material", "", parts);
    if (!sameList(before.textures, after.textures, sameTexture) && parts.empty()) parts.emplace_back("textures");
    describeItems(before.lights, after.lights, lightChanges, "light", "light ", parts);

    const CameraDesc &a = before.camera, &b = after.camera;
    std::vector<std::string> camera;
    if (a.eye != b.eye || a.target != b.target || a.up != b.up || a.resolution != b.resolution) camera.emplace_back("camera");
    else {
        if (a.vfovDeg != b.vfovDeg) camera.emplace_back("field of view");
        if (a.apertureRadius != b.apertureRadius) camera.emplace_back("aperture");
        if (a.focusDistance != b.focusDistance) camera.emplace_back("focus distance");
    }
    if (camera.size() > 1) camera = {"camera"};
    parts.insert(parts.end(), camera.begin(), camera.end());

    std::vector<std::string> environment;
    if (before.environmentMap != after.environmentMap) environment.emplace_back("environment map");
    if (before.environmentIntensity != after.environmentIntensity) environment.emplace_back("environment intensity");
    if (before.environmentRotationDeg != after.environmentRotationDeg) environment.emplace_back("environment rotation");
    if (before.environment != after.environment) environment.emplace_back("environment colour");
    if (environment.size() > 1) environment = {"environment"};
    parts.insert(parts.end(), environment.begin(), environment.end());
    return joinedWithAnd(parts);
}

std::string editsProblem(const SceneEdits& edits) {
    if (std::string problem = cameraEditsProblem(edits.camera); !problem.empty()) return problem;
    if (std::string p = vectorOutOfRange(ranges::kRadiance, edits.environment, "environment colour"); !p.empty()) return p;
    if (std::string p = outOfRange(ranges::kEnvironmentIntensity, edits.environmentIntensity, "environment intensity"); !p.empty())
        return p;
    if (!std::isfinite(edits.environmentRotationDeg)) return "environment rotation is not finite";
    for (const Material& material : edits.materials)
        if (std::string problem = materialProblem(material, edits.textures.size()); !problem.empty()) return problem;
    for (const Light& light : edits.lights)
        if (std::string problem = lightProblem(light); !problem.empty()) return problem;
    return {};
}

std::string mediumBoundaryProblem(const Scene& scene) {
    const std::optional<OpenMediumBoundary> open = findOpenMediumBoundary(scene);
    return open ? "shape '" + scene.shapes[open->shape].name + "': " + open->what : std::string();
}

namespace {

// Whether the same materials bound a medium in both (so the shapes' closure need not be looked at again).
bool sameMediumBoundaries(const std::vector<Material>& a, const std::vector<Material>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].boundsMedium() != b[i].boundsMedium()) return false;
    return true;
}

} // namespace

// ---- the history --------------------------------------------------------------------------------

EditHistory::EditHistory(std::size_t maxSteps) : maxSteps_(std::max<std::size_t>(maxSteps, 1)) {
    steps_.push_back(Step{});
}

void EditHistory::reset(SceneEdits state) {
    steps_.clear();
    steps_.push_back(Step{std::move(state), {}});
    cursor_ = 0;
    refused_.clear();
}

bool EditHistory::record(const Scene& scene, const std::shared_ptr<const EnvironmentMap>& map, bool inProgress,
                         std::string label) {
    if (sameEdits(current(), scene)) {
        refused_.clear();
        return false;
    }
    if (inProgress) return false;
    SceneEdits state = SceneEdits::of(scene, map);
    // Only a problem the edit brought: one the file itself has (a loader laxer than these checks)
    // must not stop every later edit from being recorded.
    refused_ = editsProblem(state);
    // The scene the history started from held its media (the loader checks), so only an edit
    // that changes which materials bound one can open a boundary.
    if (refused_.empty() && !sameMediumBoundaries(state.materials, current().materials))
        refused_ = mediumBoundaryProblem(scene);
    if (!refused_.empty() && refused_ != editsProblem(current())) return false;
    refused_.clear();
    if (label.empty()) label = describeEdit(current(), state);
    steps_.erase(steps_.begin() + static_cast<std::ptrdiff_t>(cursor_) + 1, steps_.end()); // no redo past a new edit
    steps_.push_back(Step{std::move(state), std::move(label)});
    ++cursor_;
    while (steps_.size() > maxSteps_ + 1) {
        steps_.pop_front();
        --cursor_;
    }
    return true;
}

std::string EditHistory::undoLabel() const { return canUndo() ? steps_[cursor_].label : std::string(); }
std::string EditHistory::redoLabel() const { return canRedo() ? steps_[cursor_ + 1].label : std::string(); }

void EditHistory::undo() {
    if (canUndo()) --cursor_;
    refused_.clear();
}

void EditHistory::redo() {
    if (canRedo()) ++cursor_;
    refused_.clear();
}

void EditHistory::rebase(const Scene& oldFile, const Scene& newFile, const SceneEdits& now) {
    // The merge reads only the parts a snapshot has: merged without the shapes, it copies no more.
    const Scene base = SceneEdits::of(oldFile).toScene(), reloaded = SceneEdits::of(newFile).toScene();
    std::deque<Step> kept;
    std::size_t cursor = 0;
    for (std::size_t i = 0; i < steps_.size(); ++i) {
        const SceneEdits& before = steps_[i].state;
        SceneEdits state = SceneEdits::of(mergeReloadedScene(base, before.toScene(), reloaded).scene);
        // A state keeps its own map, or has the file's, which the merged scene has too.
        if (state.environmentMap == before.environmentMap) state.environmentMapData = before.environmentMapData;
        else if (state.environmentMap == now.environmentMap) state.environmentMapData = now.environmentMapData;
        // A step whose change the file overrode changes nothing any more: it goes.
        if (kept.empty() || !sameEdits(kept.back().state, state)) kept.push_back(Step{std::move(state), steps_[i].label});
        if (i == cursor_) cursor = kept.size() - 1;
    }
    kept.front().label.clear();
    steps_ = std::move(kept);
    cursor_ = cursor;
}

void EditHistory::shareEnvironmentMap(const std::filesystem::path& path, const std::shared_ptr<const EnvironmentMap>& map) {
    for (Step& step : steps_)
        if (step.state.environmentMap == path) step.state.environmentMapData = map;
}

} // namespace ptview
