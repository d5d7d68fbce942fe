#pragma once
// Which keys each material type takes in a scene file. The loader, the writer and the materials
// panel all read this one table, so a type cannot gain a key in one of them and not the others.

#include "Scene.h"
#include "SchemaKeys.h"

#include <glm/glm.hpp>

#include <optional>
#include <string_view>
#include <vector>

namespace ptview {

// Every type but emitter has one colour, under the name users know for that model (it is also
// the panel's label); ior and roughness only where the model has them; every type may emit.
struct MaterialSchema {
    const char* name; // the JSON "type"
    MaterialType type;
    const char* colorKey;                  // nullptr: the type has no colour (emitter: "radiance")
    std::optional<glm::vec3> colorDefault; // nullopt: the colour is required
    bool hasIor;
    bool hasRoughness;
    // Where Material::radiance is read and written: "radiance" (emitter: its only effect, so
    // required) or "emission" (everything else: optional, default black, written only when not).
    const char* radianceKey;
    bool radianceRequired;
};

// In MaterialType order, so kMaterialSchemas[int(type)] is the schema of type.
inline const MaterialSchema kMaterialSchemas[] = {
    {"diffuse", MaterialType::Diffuse, "albedo", std::nullopt, false, false, "emission", false},
    {"emitter", MaterialType::Emitter, nullptr, std::nullopt, false, false, "radiance", true},
    {"diffuse_transmission", MaterialType::DiffuseTransmission, "transmittance", std::nullopt, false, false, "emission", false},
    {"mirror", MaterialType::Mirror, "reflectance", glm::vec3(1.0f), false, false, "emission", false},
    {"specular_transmission", MaterialType::SpecularTransmission, "transmittance", glm::vec3(1.0f), true, false, "emission", false},
    {"glass", MaterialType::Glass, "tint", glm::vec3(1.0f), true, false, "emission", false},
    {"metal", MaterialType::Metal, "reflectance", std::nullopt, false, true, "emission", false},
    {"plastic", MaterialType::Plastic, "albedo", std::nullopt, true, true, "emission", false},
    {"principled", MaterialType::Principled, "base_color", glm::vec3(1.0f), true, true, "emission", false},
};

inline const MaterialSchema& materialSchema(MaterialType type) {
    return kMaterialSchemas[static_cast<int>(type)];
}

// nullptr when no type has that name.
inline const MaterialSchema* findMaterialSchema(std::string_view name) { return findSchemaNamed(kMaterialSchemas, name); }

// The glTF metallic-roughness inputs only the principled model has, after its emission.
inline const char* const kPrincipledOnlyKeys[] = {"metallic", "transmission", "alpha", "alpha_mode", "alpha_cutoff",
                                                  "emission_strength", "normal_map"};

// Every key a material of this type may have, in the order the loader lists them.
inline std::vector<const char*> materialKeys(const MaterialSchema& schema) {
    std::vector<const char*> keys = {"type"};
    if (schema.radianceRequired) keys.push_back(schema.radianceKey);
    if (schema.colorKey) keys.push_back(schema.colorKey);
    if (schema.hasIor) keys.push_back("ior");
    if (schema.hasRoughness) keys.push_back("roughness");
    if (!schema.radianceRequired) keys.push_back(schema.radianceKey);
    if (schema.type == MaterialType::Principled)
        keys.insert(keys.end(), std::begin(kPrincipledOnlyKeys), std::end(kPrincipledOnlyKeys));
    return keys;
}

// The fields of a material that one key of `schema` sets, copied from `from` to `to`: a textured
// input's factor and slot, the emitter's radiance alone, "emission_strength" none (it scales the
// emission as read). An override of a glTF material keeps the file's value of a key it leaves out
// this way, and the writer finds the keys an override must hold by which copies change something.
inline void copyMaterialInput(const MaterialSchema& schema, std::string_view key, const Material& from, Material& to) {
    if (key == "type") {
        to.type = from.type;
    } else if (key == schema.radianceKey) {
        to.radiance = from.radiance;
        if (!schema.radianceRequired) to.emissionTexture = from.emissionTexture;
    } else if (schema.colorKey && key == schema.colorKey) {
        to.color = from.color;
        to.baseColorTexture = from.baseColorTexture;
    } else if (key == "ior") {
        to.ior = from.ior;
    } else if (key == "roughness") {
        to.roughness = from.roughness;
        to.roughnessTexture = from.roughnessTexture;
    } else if (key == "metallic") {
        to.metallic = from.metallic;
        to.metallicTexture = from.metallicTexture;
    } else if (key == "transmission") {
        to.transmission = from.transmission;
    } else if (key == "alpha") {
        to.alpha = from.alpha;
    } else if (key == "alpha_mode") {
        to.alphaMode = from.alphaMode;
    } else if (key == "alpha_cutoff") {
        to.alphaCutoff = from.alphaCutoff;
    } else if (key == "normal_map") {
        to.normalScale = from.normalScale;
        to.normalTexture = from.normalTexture;
    }
}

// Every key some material type has, each once, in the order of first appearance in the table:
// the keys allowed while a material's type is not known.
inline std::vector<const char*> anyMaterialKeys() {
    std::vector<const char*> keys;
    for (const MaterialSchema& schema : kMaterialSchemas) appendNewKeys(keys, materialKeys(schema));
    return keys;
}

} // namespace ptview
