// Writes the scene model as JSON. The document is built as an ordered nlohmann tree (which keeps
// key order and escapes strings) and printed by a small printer of our own, for two things
// nlohmann's dump cannot do: short arrays and objects on one line, and floats in the shortest
// form that the loader reads back as the same float (dump prints the double, 0.7300000190734863,
// and a float edited in the viewer as 0.059999995 where 0.06 is the same float).

#include <ptview/scene/SceneWriter.h>

#include <ptview/scene/GltfLoader.h>
#include <ptview/io/ImageIO.h>
#include <ptview/scene/MaterialInputs.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/scene/SceneRanges.h>
#include <ptview/scene/LightSchema.h>
#include <ptview/scene/ShapeSchema.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <stdexcept>

namespace ptview {
namespace {

using Json = nlohmann::ordered_json;

// Containers whose one-line form fits this many columns (indent, key and comma included) stay on
// one line, except the top level and the sections in it that hold more than one entry (camera,
// materials, shapes, lights), which read better one entry a line whatever their size.
constexpr std::size_t kLineWidth = 120;

[[noreturn]] void fail(const std::string& pointer, const std::string& reason) {
    throw std::runtime_error(pointer + ": " + reason);
}

// Floats are stored in the tree as the double of the float, which converts back exactly.
Json number(float value) {
    return static_cast<double>(value);
}

Json vec3(const glm::vec3& v) {
    return Json::array({number(v.x), number(v.y), number(v.z)});
}

// Whether the loader reads text back as value: it reads a number with strtod and keeps it only
// when it fits a float, then rounds it to float.
bool readsBackAs(const char* text, float value) {
    double read = std::strtod(text, nullptr);
    return std::abs(read) <= std::numeric_limits<float>::max() && static_cast<float>(read) == value;
}

// The fewest significant digits that read back as the same float: std::to_chars gives them for
// a float read directly; the loader reads through a double first, which in principle can round a
// decimal next to the midpoint of two floats onto it, so that is checked, with more digits as
// the fallback. They are then written as people write numbers: positional (1000, 0.001) unless
// that would take many zeros (1e-30, 3.4028235e38).
std::string formatFloat(float value, const std::string& pointer) {
    if (!std::isfinite(value)) fail(pointer, "cannot write a number that is not finite");
    // nlohmann reads "-0" as the integer 0, which has no sign.
    if (value == 0.0f) return std::signbit(value) ? "-0.0" : "0";
    char scientific[64];
    std::to_chars_result shortest = std::to_chars(scientific, scientific + sizeof scientific - 1, value,
                                                  std::chars_format::scientific);
    *shortest.ptr = '\0';
    for (int digits = 10; !readsBackAs(scientific, value) && digits <= 17; ++digits) // 17 give the double exactly
        std::snprintf(scientific, sizeof scientific, "%.*e", digits - 1, static_cast<double>(value));
    // scientific is "[-]d[.ddd]e±XX": split it into sign, digits and the exponent of the first digit.
    std::string text = scientific;
    std::size_t e = text.find('e');
    int exponent = std::atoi(text.c_str() + e + 1);
    std::string mantissa = text.substr(0, e);
    std::string sign = mantissa[0] == '-' ? "-" : "";
    std::string digits;
    for (char c : mantissa)
        if (c >= '0' && c <= '9') digits += c;
    int count = static_cast<int>(digits.size());
    if (exponent >= 16 || exponent < -6) {
        std::string result = sign + digits.substr(0, 1);
        if (count > 1) result += "." + digits.substr(1);
        return result + "e" + std::to_string(exponent);
    }
    if (exponent < 0) return sign + "0." + std::string(static_cast<std::size_t>(-exponent - 1), '0') + digits;
    if (count <= exponent + 1) return sign + digits + std::string(static_cast<std::size_t>(exponent + 1 - count), '0');
    return sign + digits.substr(0, static_cast<std::size_t>(exponent + 1)) + "." +
           digits.substr(static_cast<std::size_t>(exponent + 1));
}

// A number the loader would refuse is refused here, naming its place, rather than written.
Json numberInRange(float value, const SceneRange& range, const std::string& pointer) {
    if (std::isfinite(value) && !range.contains(value))
        fail(pointer, "cannot write " + formatFloat(value, pointer) + ": the " + range.quantity + " must be " + range.text());
    return number(value);
}

Json vec3InRange(const glm::vec3& v, const SceneRange& range, const std::string& pointer) {
    Json json = Json::array();
    for (int i = 0; i < 3; ++i) json.push_back(numberInRange(v[i], range, pointer + "/" + std::to_string(i)));
    return json;
}

// --- Printer -------------------------------------------------------------------------------------

std::string scalarText(const Json& value, const std::string& pointer) {
    switch (value.type()) {
    case Json::value_t::number_float: return formatFloat(static_cast<float>(value.get<double>()), pointer);
    case Json::value_t::string:
        try {
            return value.dump();
        } catch (const Json::exception&) {
            fail(pointer, "text is not valid UTF-8");
        }
    default: return value.dump();
    }
}

std::string joinPointer(const std::string& pointer, const std::string& token) {
    std::string escaped;
    for (char c : token) escaped += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
    return pointer + "/" + escaped;
}

std::string keyText(const std::string& key, const std::string& pointer) {
    return scalarText(Json(key), pointer) + ": ";
}

std::string oneLine(const Json& value, const std::string& pointer) {
    if (value.is_array()) {
        std::string text = "[";
        for (std::size_t i = 0; i < value.size(); ++i)
            text += (i ? ", " : "") + oneLine(value[i], pointer + "/" + std::to_string(i));
        return text + "]";
    }
    if (value.is_object()) {
        std::string text = "{";
        bool first = true;
        for (auto it = value.begin(); it != value.end(); ++it) {
            std::string at = joinPointer(pointer, it.key());
            text += (first ? "" : ", ") + keyText(it.key(), at) + oneLine(it.value(), at);
            first = false;
        }
        return text + "}";
    }
    return scalarText(value, pointer);
}

// Appends value, whose line already holds `prefix` columns (indent, key and comma), to out.
void print(const Json& value, const std::string& pointer, int depth, std::size_t prefix, std::string& out) {
    std::string line = oneLine(value, pointer);
    bool isContainer = value.is_array() || value.is_object();
    bool isSection = depth == 0 || (depth == 1 && value.size() > 1);
    if (!isContainer || value.empty() || (!isSection && prefix + line.size() <= kLineWidth)) {
        out += line;
        return;
    }
    std::string inner(static_cast<std::size_t>(2 * depth + 2), ' ');
    out += value.is_array() ? "[\n" : "{\n";
    std::size_t index = 0;
    for (auto it = value.begin(); it != value.end(); ++it, ++index) {
        std::string at = value.is_array() ? pointer + "/" + std::to_string(index) : joinPointer(pointer, it.key());
        std::string key = value.is_object() ? keyText(it.key(), at) : "";
        out += inner + key;
        print(it.value(), at, depth + 1, inner.size() + key.size() + 1, out);
        out += index + 1 < value.size() ? ",\n" : "\n";
    }
    out += std::string(static_cast<std::size_t>(2 * depth), ' ') + (value.is_array() ? "]" : "}");
}

// --- Scene parts ---------------------------------------------------------------------------------

Json cameraJson(const CameraDesc& camera) {
    Json json;
    json["eye"] = vec3(camera.eye);
    json["target"] = vec3(camera.target);
    json["up"] = vec3(camera.up);
    json["vfov_deg"] = numberInRange(camera.vfovDeg, ranges::kVerticalFov, "/camera/vfov_deg");
    json["resolution"] = Json::array({camera.resolution.x, camera.resolution.y});
    // A pinhole camera's file stays as it was unless its focus was moved off the target.
    if (camera.apertureRadius != 0.0f)
        json["aperture_radius"] = numberInRange(camera.apertureRadius, ranges::kApertureRadius, "/camera/aperture_radius");
    if (camera.apertureRadius != 0.0f || camera.focusDistance != defaultFocusDistance(camera))
        json["focus_distance"] = numberInRange(camera.focusDistance, ranges::kFocusDistance, "/camera/focus_distance");
    return json;
}

std::string relativePathText(const std::filesystem::path& map, const std::filesystem::path& fileDirectory);

// A textured input as the loader reads it (readTexturedInput): the plain value when there is no
// texture, else {"texture", "factor", and scale, offset, wrap, filter where not the defaults}.
Json texturedJson(Json factor, const TextureSlot& slot, const Scene& scene, const std::string& pointer) {
    if (!slot.used()) return factor;
    if (static_cast<std::size_t>(slot.texture) >= scene.textures.size())
        fail(pointer, "texture index " + std::to_string(slot.texture) + " is out of range");
    const SceneTexture& texture = scene.textures[static_cast<std::size_t>(slot.texture)];
    if (texture.file.empty())
        fail(pointer, "the texture " + texture.source + " is embedded in another file, which a scene file cannot name");
    Json json;
    json["texture"] = relativePathText(texture.file, scene.path.parent_path());
    json["factor"] = std::move(factor);
    if (slot.scale != glm::vec2(1.0f)) json["scale"] = Json::array({slot.scale.x, slot.scale.y});
    if (slot.offset != glm::vec2(0.0f)) json["offset"] = Json::array({slot.offset.x, slot.offset.y});
    if (texture.wrapU != TextureWrap::Repeat || texture.wrapV != TextureWrap::Repeat) {
        const EnumTable<TextureWrap>& wrapNames = textureWrapNames();
        if (texture.wrapU == texture.wrapV) json["wrap"] = wrapNames.name(texture.wrapU);
        else json["wrap"] = Json::array({wrapNames.name(texture.wrapU), wrapNames.name(texture.wrapV)});
    }
    if (!texture.bilinear) json["filter"] = "nearest";
    return json;
}

// An input's factor: its value where its range holds it, or its name.
Json inputFactorJson(const MaterialInput& input, const Material& material, const std::string& pointer) {
    switch (input.value) {
    case InputValue::Vector: return vec3InRange(material.*input.vector, *input.range, pointer);
    case InputValue::Number: return numberInRange(material.*input.number, *input.range, pointer);
    case InputValue::AlphaMode: return alphaModeNames().name(material.alphaMode);
    case InputValue::Interior:
        return Json{{"sigma_a", vec3InRange(material.sigmaA, ranges::kMediumCoefficient, pointer + "/sigma_a")},
                    {"sigma_s", vec3InRange(material.sigmaS, ranges::kMediumCoefficient, pointer + "/sigma_s")},
                    {"g", numberInRange(material.g, ranges::kPhaseAsymmetry, pointer + "/g")}};
    case InputValue::Strength: break;
    }
    fail(pointer, "no value is written for this key"); // emission_strength: the emission holds it
}

Json materialJson(const Material& material, const std::string& pointer, const Scene& scene) {
    const MaterialSchema& schema = materialSchema(material.type);
    Json json;
    json["type"] = schema.name;
    for (const MaterialInput& input : kMaterialInputs) {
        if (!input.takenBy(schema) || !materialInputWritten(input, material)) continue;
        const char* key = materialInputKey(input, schema);
        const std::string at = pointer + "/" + key;
        Json factor = inputFactorJson(input, material, at);
        json[key] = input.slot ? texturedJson(std::move(factor), material.*input.slot, scene, at) : std::move(factor);
    }
    return json;
}

// A textured input of an override (docs/scene-format.md, `gltf`): when the slot holds the file's
// own texture, the object form without "texture" (the file's texture may be embedded in a .glb,
// which no path names), with the scale and offset where they differ from the file's; else as a
// material of the scene writes it (a plain value: no texture).
Json overrideTexturedJson(Json factor, const TextureSlot& slot, const TextureSlot& fileSlot, const Scene& scene,
                          const std::string& pointer) {
    if (!slot.used() || slot.texture != fileSlot.texture) return texturedJson(std::move(factor), slot, scene, pointer);
    Json json{{"factor", std::move(factor)}};
    if (slot.scale != fileSlot.scale) json["scale"] = Json::array({slot.scale.x, slot.scale.y});
    if (slot.offset != fileSlot.offset) json["offset"] = Json::array({slot.offset.x, slot.offset.y});
    return json;
}

// One key of an override: the material's value of that input, written even where a material of
// the scene would leave it out as the default (the file's value may differ from the default).
Json overrideKeyJson(const std::string& key, const Material& material, const Material& file, const Scene& scene,
                     const std::string& pointer) {
    const MaterialSchema& schema = materialSchema(material.type);
    const std::string at = pointer + "/" + key;
    if (key == "type") return schema.name;
    const MaterialInput* input = findMaterialInput(schema, key);
    if (!input || input->value == InputValue::Strength) fail(at, "no override is written for this key");
    Json factor = inputFactorJson(*input, material, at);
    // A plain number for the normal map: no normal map (the scale kept).
    if (!input->slot) return factor;
    return overrideTexturedJson(std::move(factor), material.*input->slot, file.*input->slot, scene, at);
}

// The keys of a material a glTF file made whose value differs from the file's, each as the
// loader reads an override: a key left out keeps the file's value, so a key is needed exactly
// when copying the material's input onto the file's changes it. Empty when the material is as
// the file made it.
Json overrideJson(const Material& material, const Material& file, const Scene& scene, const std::string& pointer) {
    const MaterialSchema& schema = materialSchema(material.type);
    Json json = Json::object();
    for (const char* key : materialKeys(schema)) {
        Material withKey = file;
        copyMaterialInput(schema, key, material, withKey);
        if (!sameMaterial(withKey, file)) json[key] = overrideKeyJson(key, material, file, scene, pointer);
    }
    return json;
}

// An import's "materials": the overrides of the materials it made, by name; empty when none differs.
Json overridesJson(const Scene& scene, int importIndex, const std::string& pointer) {
    const SceneImport& entry = scene.imports[static_cast<std::size_t>(importIndex)];
    Json overrides = Json::object();
    for (const Material& material : scene.materials) {
        if (material.importedFrom != importIndex) continue;
        const std::string at = joinPointer(pointer, material.name);
        auto file = std::find_if(entry.fileMaterials.begin(), entry.fileMaterials.end(),
                                 [&](const Material& m) { return m.name == material.name; });
        if (file == entry.fileMaterials.end()) fail(at, "no material of " + entry.file.filename().string() + " has this name");
        Json json = overrideJson(material, *file, scene, at);
        if (!json.empty()) overrides[material.name] = std::move(json);
    }
    return overrides;
}

Json materialName(const std::vector<Material>& materials, int index, const std::string& pointer) {
    if (index < 0 || static_cast<std::size_t>(index) >= materials.size())
        fail(pointer, "material index " + std::to_string(index) + " is out of range");
    return materials[static_cast<std::size_t>(index)].name;
}

Json transformJson(const Transform& transform) {
    Json json = Json::object();
    if (transform.translate != glm::vec3(0.0f)) json["translate"] = vec3(transform.translate);
    if (transform.rotationDeg != 0.0f)
        json["rotation"] = Json{{"axis", vec3(transform.rotationAxis)}, {"degrees", number(transform.rotationDeg)}};
    if (transform.scale != glm::vec3(1.0f)) json["scale"] = vec3(transform.scale);
    return json;
}

// Every slot named, so the file reads back to the same materials whatever the mesh's MTL says.
Json meshShapeJson(const Shape& shape, const Scene& scene, const std::string& pointer) {
    Json json;
    json["name"] = shape.name;
    json["type"] = shapeSchema(ShapeType::Mesh).name;
    if (shape.mesh < 0 || static_cast<std::size_t>(shape.mesh) >= scene.meshes.size())
        fail(pointer + "/mesh", "mesh index " + std::to_string(shape.mesh) + " is out of range");
    const SceneMesh& mesh = scene.meshes[static_cast<std::size_t>(shape.mesh)];
    json["mesh"] = mesh.name;
    const std::vector<std::string>& slots = mesh.data->materialSlots;
    Json bySlot = Json::object();
    for (std::size_t slot = 0; slot < slots.size() && slot < shape.slotMaterials.size(); ++slot) {
        Json name = materialName(scene.materials, shape.slotMaterials[slot], pointer + "/materials");
        if (slots[slot].empty())
            json["material"] = name; // faces without usemtl
        else
            bySlot[slots[slot]] = name;
    }
    if (!bySlot.empty()) json["materials"] = std::move(bySlot);
    Json transform = transformJson(shape.transform);
    if (!transform.empty()) json["transform"] = std::move(transform);
    return json;
}

Json shapeJson(const Shape& shape, const Scene& scene, const std::string& pointer) {
    if (shape.type == ShapeType::Mesh) return meshShapeJson(shape, scene, pointer);
    const std::vector<Material>& materials = scene.materials;
    Json json;
    json["name"] = shape.name;
    json["type"] = shapeSchema(shape.type).name;
    switch (shape.type) {
    case ShapeType::Sphere:
        json["center"] = vec3(shape.center);
        json["radius"] = number(shape.radius);
        break;
    case ShapeType::Quad:
        json["center"] = vec3(shape.center);
        json["u"] = vec3(shape.u);
        json["v"] = vec3(shape.v);
        break;
    case ShapeType::Box:
        json["center"] = vec3(shape.center);
        json["half_size"] = vec3(shape.halfSize);
        if (shape.rotationDeg != 0.0f)
            json["rotation"] = Json{{"axis", vec3(shape.rotationAxis)}, {"degrees", number(shape.rotationDeg)}};
        break;
    case ShapeType::Disk:
        json["center"] = vec3(shape.center);
        json["normal"] = vec3(shape.normal);
        json["radius"] = number(shape.radius);
        break;
    case ShapeType::Mesh:
        break;
    }
    json["material"] = materialName(materials, shape.material, pointer + "/material");
    return json;
}

Json lightJson(const Light& light, const std::string& pointer) {
    Json json;
    json["name"] = light.name;
    json["type"] = lightSchema(light.type).name;
    if (light.type != LightType::Directional) json["position"] = vec3(light.position);
    if (light.type != LightType::Point) json["direction"] = vec3(light.direction);
    json["intensity"] = vec3InRange(light.intensity, ranges::kIntensity, pointer + "/intensity");
    if (light.type == LightType::Spot) {
        json["inner_deg"] = numberInRange(light.innerAngleDeg, ranges::kSpotConeAngle, pointer + "/inner_deg");
        json["outer_deg"] = numberInRange(light.outerAngleDeg, ranges::kSpotConeAngle, pointer + "/outer_deg");
        if (!ranges::coneAnglesOrdered(light.innerAngleDeg, light.outerAngleDeg))
            fail(pointer + "/inner_deg", "must not exceed outer_deg");
    }
    return json;
}

// The lights of import importIndex that differ from the file's, each whole
// but for its name, which is the key (docs/scene-format.md, `gltf`).
Json lightOverridesJson(const Scene& scene, int importIndex, const std::string& pointer) {
    const SceneImport& entry = scene.imports[static_cast<std::size_t>(importIndex)];
    Json overrides = Json::object();
    for (const Light& light : scene.lights) {
        if (light.importedFrom != importIndex) continue;
        // Compared as fields, not as written: a file's light need not be one our format can hold (a glTF spot's
        // inner cone angle is 0 by default, which "inner_deg" refuses), and unedited it is not written.
        auto file = std::find_if(entry.fileLights.begin(), entry.fileLights.end(),
                                 [&](const Light& l) { return sameLight(l, light); });
        if (file != entry.fileLights.end()) continue;
        Json json = lightJson(light, joinPointer(pointer, light.name));
        json.erase("name");
        overrides[light.name] = std::move(json);
    }
    return overrides;
}

// A file's path (an environment map, a mesh) as the loader resolves it: relative to the directory the scene file is read
// from, or absolute when the two share nothing below the root (a relative path would then climb
// all the way up).
std::string relativePathText(const std::filesystem::path& map, const std::filesystem::path& fileDirectory) {
    namespace fs = std::filesystem;
    fs::path target = fs::absolute(map).lexically_normal();
    fs::path base = fs::absolute(fileDirectory.empty() ? fs::path(".") : fileDirectory).lexically_normal();
    auto t = target.begin(), b = base.begin();
    bool sharesTop = target.root_path() == base.root_path() && std::distance(t, target.end()) > 1 &&
                     std::distance(b, base.end()) > 1 && *std::next(t) == *std::next(b);
    fs::path relative = sharesTop ? target.lexically_relative(base) : fs::path();
    return (relative.empty() ? target : relative).generic_u8string();
}

Json environmentJson(const Scene& scene) {
    if (scene.environmentMap.empty())
        return Json{{"color", vec3InRange(scene.environment, ranges::kRadiance, "/environment/color")}};
    return Json{{"map", relativePathText(scene.environmentMap, scene.path.parent_path())},
                {"intensity", numberInRange(scene.environmentIntensity, ranges::kEnvironmentIntensity, "/environment/intensity")},
                {"rotation_deg", numberInRange(scene.environmentRotationDeg, ranges::kEnvironmentRotation, "/environment/rotation_deg")}};
}


// Whether two slots, of a material of `a` and one of `b`, read the same texture the same way:
// the file read back has its own texture list, in which a texture the user loaded twice is one
// entry, so the entries are compared by sampler and pixels rather than by index.
bool sameSlotAcross(const TextureSlot& slotA, const Scene& a, const TextureSlot& slotB, const Scene& b) {
    if (slotA.used() != slotB.used() || slotA.scale != slotB.scale || slotA.offset != slotB.offset) return false;
    if (!slotA.used()) return true;
    const SceneTexture& x = a.textures.at(static_cast<std::size_t>(slotA.texture));
    const SceneTexture& y = b.textures.at(static_cast<std::size_t>(slotB.texture));
    if (x.colorSpace != y.colorSpace || x.wrapU != y.wrapU || x.wrapV != y.wrapV || x.bilinear != y.bilinear) return false;
    if (x.image == y.image) return true;
    return x.image && y.image && x.image->width == y.image->width && x.image->height == y.image->height &&
           x.image->rgba == y.image->rgba;
}

// The first material a glTF file made that the file read back does not give as it is in memory
// (every field, as sameMaterial; textures by what they read); nullptr when every one comes back.
const Material* importedMaterialNotReadBack(const Scene& edited, const Scene& readBack) {
    static TextureSlot Material::*const slots[] = {&Material::baseColorTexture, &Material::roughnessTexture,
                                                   &Material::metallicTexture, &Material::normalTexture,
                                                   &Material::emissionTexture};
    for (const Material& material : edited.materials) {
        if (material.importedFrom < 0) continue;
        auto back = std::find_if(readBack.materials.begin(), readBack.materials.end(),
                                 [&](const Material& m) { return m.name == material.name; });
        if (back == readBack.materials.end()) return &material;
        Material compared = *back; // with the slots of the same textures as in memory
        for (TextureSlot Material::*slot : slots) {
            if (!sameSlotAcross(material.*slot, edited, (*back).*slot, readBack)) return &material;
            compared.*slot = material.*slot;
        }
        if (!sameMaterial(compared, material)) return &material;
    }
    return nullptr;
}

} // namespace

std::string sceneToJson(const Scene& scene) {
    Json root;
    root["camera"] = cameraJson(scene.camera);
    root["environment"] = environmentJson(scene);

    Json materials = Json::object();
    for (const Material& material : scene.materials) {
        if (material.importedFrom >= 0) continue; // written as its glTF file, below
        // Shapes name their material, so a second one of the same name could not be told apart.
        if (materials.contains(material.name))
            fail(joinPointer("/materials", material.name), "two materials have this name");
        materials[material.name] = materialJson(material, joinPointer("/materials", material.name), scene);
    }
    root["materials"] = std::move(materials);

    Json meshes = Json::object();
    for (const SceneMesh& mesh : scene.meshes)
        if (mesh.importedFrom < 0) meshes[mesh.name] = Json{{"file", relativePathText(mesh.file, scene.path.parent_path())}};
    if (!meshes.empty()) root["meshes"] = std::move(meshes);

    Json shapes = Json::array();
    for (const Shape& shape : scene.shapes)
        if (shape.importedFrom < 0) shapes.push_back(shapeJson(shape, scene, "/shapes/" + std::to_string(shapes.size())));
    root["shapes"] = std::move(shapes);

    Json lights = Json::array();
    for (const Light& light : scene.lights)
        if (light.importedFrom < 0) lights.push_back(lightJson(light, "/lights/" + std::to_string(lights.size())));
    if (!lights.empty()) root["lights"] = std::move(lights);

    // A glTF file's parts are written as the reference to it, and edits to its materials as
    // overrides in that reference.
    if (!scene.imports.empty()) {
        Json imports = Json::array();
        for (const SceneImport& entry : scene.imports) {
            const std::string at = "/gltf/" + std::to_string(imports.size());
            Json json{{"file", relativePathText(entry.file, scene.path.parent_path())}};
            Json transform = transformJson(entry.transform);
            if (!transform.empty()) json["transform"] = std::move(transform);
            Json overrides = overridesJson(scene, static_cast<int>(imports.size()), at + "/materials");
            if (!overrides.empty()) json["materials"] = std::move(overrides);
            Json lightOverrides = lightOverridesJson(scene, static_cast<int>(imports.size()), at + "/lights");
            if (!lightOverrides.empty()) json["lights"] = std::move(lightOverrides);
            imports.push_back(std::move(json));
        }
        root["gltf"] = std::move(imports);
    }

    std::string text;
    print(root, "", 0, 0, text);
    return text + "\n";
}

void saveScene(const Scene& scene, const std::filesystem::path& path) {
    // A glTF file opened on its own has it as its path; our JSON must not replace it.
    if (isGltfFile(path))
        throw std::runtime_error(path.string() + ": a glTF file is not overwritten with a scene; save as a .json (not saved)");
    std::string text;
    try {
        Scene placed = scene; // the environment map's path is written relative to the new file
        placed.path = path;
        text = sceneToJson(placed);
        // Names the file already: parseScene's messages start with the source name.
        const Scene readBack = parseScene(text, path);
        // A material of our own is written whole; one a glTF file made is written as the keys
        // that differ from the file's, which must give it back exactly.
        if (const Material* lost = importedMaterialNotReadBack(placed, readBack))
            throw std::runtime_error("the material \"" + lost->name + "\" would not load back as it is");
    } catch (const SceneError& error) {
        throw std::runtime_error(std::string(error.what()) + " (not saved: it would not load back)");
    } catch (const std::runtime_error& error) {
        throw std::runtime_error(path.string() + ": " + error.what() + " (not saved)");
    }
    writeFileAtomically(path, text);
}

} // namespace ptview
