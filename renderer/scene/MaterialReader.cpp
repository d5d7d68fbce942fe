#include <ptview/scene/MaterialReader.h>

#include <ptview/scene/MaterialInputs.h>
#include <ptview/scene/MaterialTextures.h>
#include <ptview/scene/SceneFileReaders.h>

#include <algorithm>
#include <iterator>

namespace ptview::sceneFile {
namespace {

TextureWrap readTextureWrap(const Json& value, const Pointer& at) { return readEnum(value, at, textureWrapNames(), "wrap mode"); }

// A material input that may be textured: its plain value (readFactor), a texture's path (the
// factor is then 1), or {"texture": path, "factor": value, "scale": [su, sv], "offset": [ou, ov],
// "wrap": "repeat" | "clamp" | "mirror" | [u mode, v mode], "filter": "linear" | "nearest"}.
// Returns the factor; a texture becomes a request for the slot.
template <typename T, typename ReadFactor>
T readTexturedInput(const Json& value, const Pointer& at, ReadFactor readFactor, T one, TextureColorSpace colorSpace,
                    std::size_t materialIndex, TextureSlot Material::*slot, std::vector<TextureRequest>& requests) {
    if (!value.is_string() && !value.is_object()) return readFactor(value, at);
    TextureRequest request{materialIndex, slot, {}, colorSpace, TextureWrap::Repeat, TextureWrap::Repeat, true, at};
    T factor = one;
    if (value.is_string()) {
        request.file = std::filesystem::u8path(readString(value, at));
    } else {
        checkKeys(value, at, {"texture", "factor", "scale", "offset", "wrap", "filter"});
        request.at = at / "texture";
        request.file = std::filesystem::u8path(readString(requireKey(value, at, "texture"), at / "texture"));
        if (const Json* f = optionalKey(value, "factor")) factor = readFactor(*f, at / "factor");
        if (const Json* scale = optionalKey(value, "scale")) readVec2(*scale, at / "scale");
        if (const Json* offset = optionalKey(value, "offset")) readVec2(*offset, at / "offset");
        if (const Json* wrap = optionalKey(value, "wrap")) {
            if (wrap->is_array()) {
                if (wrap->size() != 2) fail(at / "wrap", "expected a wrap mode or an array of 2 (u, v)");
                request.wrapU = readTextureWrap((*wrap)[0], at / "wrap" / 0);
                request.wrapV = readTextureWrap((*wrap)[1], at / "wrap" / 1);
            } else {
                request.wrapU = request.wrapV = readTextureWrap(*wrap, at / "wrap");
            }
        }
        if (const Json* filter = optionalKey(value, "filter")) {
            std::string name = readString(*filter, at / "filter");
            if (name != "linear" && name != "nearest")
                fail(at / "filter", "unknown filter \"" + name + "\" (expected linear or nearest)");
            request.bilinear = name == "linear";
        }
    }
    if (request.file.empty()) fail(request.at, "expected a file name, got an empty string");
    requests.push_back(request);
    return factor;
}

// The scale and offset of a textured input's object form, applied to its slot once it is made.
void readTextureTransform(const Json& value, const Pointer& at, TextureSlot& slot) {
    if (!value.is_object()) return;
    if (const Json* scale = optionalKey(value, "scale")) slot.scale = readVec2(*scale, at / "scale");
    if (const Json* offset = optionalKey(value, "offset")) slot.offset = readVec2(*offset, at / "offset");
}

// An input's factor as the table's range bounds it: a number, or each component of a vector.
float readFactor(const Json& value, const Pointer& at, const SceneRange& range, float*) {
    return readInRange(value, at, range);
}

glm::vec3 readFactor(const Json& value, const Pointer& at, const SceneRange& range, glm::vec3*) {
    return readVec3InRange(value, at, range);
}

// One input of a material that may be textured (MaterialInputs.h: it has a slot), into its slot;
// returns its factor. With `base` (an override), an object without "texture" keeps the file's
// texture and sets its factor, scale or offset, and the factor of the file's when it gives none.
template <typename T>
T readTexturedFactor(const MaterialInput& input, const Json& value, const Pointer& at, std::size_t index,
                     std::vector<TextureRequest>& textures, const Material* base, T fileFactor, Material& material) {
    auto read = [&input](const Json& v, const Pointer& p) { return readFactor(v, p, *input.range, static_cast<T*>(nullptr)); };
    TextureSlot& slot = material.*input.slot;
    if (base && value.is_object() && !value.contains("texture")) {
        checkKeys(value, at, {"texture", "factor", "scale", "offset"});
        slot = (*base).*input.slot;
        readTextureTransform(value, at, slot);
        const Json* factor = optionalKey(value, "factor");
        return factor ? read(*factor, at / "factor") : fileFactor;
    }
    // A texture replaces the slot whole; a plain value leaves none (an override's slot may have one).
    if (value.is_string() || value.is_object()) slot = TextureSlot{};
    else slot.texture = -1;
    T factor = readTexturedInput(value, at, read, T(1.0f), colorSpaceOf(input.slot), index, input.slot, textures);
    readTextureTransform(value, at, slot);
    return factor;
}

// A refracting material's "interior": {"sigma_a": rgb, "sigma_s": rgb, "g": number}, each
// optional (0 when left out): {} is a clear solid, whose inside holds no medium of its outside.
void readInterior(const Json& value, const Pointer& at, Material& material) {
    requireObject(value, at);
    checkKeys(value, at, {"sigma_a", "sigma_s", "g"});
    material.hasInterior = true;
    material.sigmaA = material.sigmaS = glm::vec3(0.0f);
    material.g = 0.0f;
    if (const Json* a = optionalKey(value, "sigma_a")) material.sigmaA = readVec3InRange(*a, at / "sigma_a", ranges::kMediumCoefficient);
    if (const Json* s = optionalKey(value, "sigma_s")) material.sigmaS = readVec3InRange(*s, at / "sigma_s", ranges::kMediumCoefficient);
    if (const Json* g = optionalKey(value, "g")) material.g = readInRange(*g, at / "g", ranges::kPhaseAsymmetry);
}

} // namespace

// A material of the "materials" section, or with `base` an override of a material a glTF file
// made (a "materials" entry of a "gltf" entry): then every key is optional, a key left out keeps
// the file's value, and "type" defaults to the file's. A type change starts from the new type's
// defaults, as the Materials panel's does, and keeps the file's value of each of its keys left
// out. A textured input in an override may be an object without "texture", which keeps the
// file's texture (which may be embedded in a .glb, where no path can name it) and sets its
// factor, scale or offset; a plain value means no texture.
Material readMaterial(const std::string& name, const Json& value, const Pointer& at, std::size_t index,
                      std::vector<TextureRequest>& textures, const Material* base) {
    requireObject(value, at);
    Material material;
    material.name = name;
    const MaterialSchema* schema = base ? &materialSchema(base->type) : nullptr;
    if (!base || value.contains("type")) {
        requireType(value, at, anyMaterialKeys());
        std::string type = readString(value.at("type"), at / "type");
        schema = findMaterialSchema(type);
        if (!schema) {
            std::string typeList;
            for (const MaterialSchema& candidate : kMaterialSchemas)
                typeList += (typeList.empty() ? "" : ", ") + std::string(candidate.name);
            fail(at / "type", "unknown material type \"" + type + "\" (expected one of: " + typeList + ")");
        }
    }
    checkKeys(value, at, materialKeys(*schema));
    if (base) {
        if (schema->type == base->type) material = *base;
        else
            for (const char* key : materialKeys(*schema))
                if (!value.contains(key)) copyMaterialInput(*schema, key, *base, material);
        material.importedFrom = base->importedFrom;
    } else {
        if (schema->colorDefault) material.color = *schema->colorDefault;
        // glTF's defaults: fully metallic and rough when the file says nothing would surprise in
        // a hand-written scene, so ours are a smooth-ish dielectric: metallic 0, roughness 0.5.
        if (schema->type == MaterialType::Principled) material.roughness = 0.5f;
    }
    material.type = schema->type;
    const Material fileValues = base ? *base : Material{};

    for (const MaterialInput* input : materialInputsInReadOrder()) {
        if (!input->takenBy(*schema)) continue;
        const char* key = materialInputKey(*input, *schema);
        const Pointer inputAt = at / key;
        const Json* json = materialInputRequired(*input, *schema) && !base ? &requireKey(value, at, key)
                                                                            : optionalKey(value, key);
        if (!json) continue;
        switch (input->value) {
        case InputValue::Vector:
            material.*input->vector =
                input->slot ? readTexturedFactor(*input, *json, inputAt, index, textures, base, fileValues.*input->vector, material)
                            : readVec3InRange(*json, inputAt, *input->range);
            break;
        case InputValue::Number:
            // Without a texture a normal map's key would say nothing, so a bare number is refused
            // rather than ignored; in an override it says that the file's normal map is removed
            // (and keeps the scale).
            if (input->write == InputWrite::WithTexture && !json->is_string() && !json->is_object() && !base)
                fail(inputAt, "expected a texture: a file name or {\"texture\": file, \"factor\": scale}");
            material.*input->number =
                input->slot ? readTexturedFactor(*input, *json, inputAt, index, textures, base, fileValues.*input->number, material)
                            : readInRange(*json, inputAt, *input->range);
            break;
        case InputValue::AlphaMode:
            material.alphaMode = readEnum(*json, inputAt, alphaModeNames(), "alpha mode");
            break;
        case InputValue::Interior: readInterior(*json, inputAt, material); break;
        case InputValue::Strength: {
            material.radiance *= readInRange(*json, inputAt, *input->range);
            const SceneRange& radiance = ranges::kRadiance;
            if (!radiance.contains(material.radiance.r) || !radiance.contains(material.radiance.g) ||
                !radiance.contains(material.radiance.b))
                fail(inputAt, "emission x strength is out of range (" + radiance.text() + ")");
            break;
        }
        }
    }
    return material;
}

int findMaterial(const std::vector<Material>& materials, const std::string& name) {
    auto it = std::find_if(materials.begin(), materials.end(),
                           [&](const Material& m) { return m.name == name; });
    return it == materials.end() ? -1 : static_cast<int>(std::distance(materials.begin(), it));
}

} // namespace ptview::sceneFile
