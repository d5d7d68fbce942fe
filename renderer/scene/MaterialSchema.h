#pragma once
// The material types of a scene file and what sets them apart: the name of each one's colour, and
// which of the inputs of MaterialInputs.h it takes. The loader, the writer and the materials panel
// all read this one table, so a type cannot gain a key in one of them and not the others.

#include <ptview/scene/Scene.h>
#include <ptview/scene/SchemaKeys.h>

#include <glm/glm.hpp>

#include <optional>
#include <string_view>

namespace ptview {

// Every type but emitter and medium has one colour, under the name users know for that model (it is also
// the panel's label); ior and roughness only where the model has them; every surface type may emit.
struct MaterialSchema {
    const char* name; // the JSON "type"
    MaterialType type;
    const char* colorKey;                  // nullptr: the type has no colour (emitter: "radiance")
    std::optional<glm::vec3> colorDefault; // nullopt: the colour is required
    bool hasIor;
    bool hasRoughness;
    // Material::radiance is the emitter's "radiance" (its only effect, so required); every other
    // type's is its optional "emission".
    bool radianceRequired;
};

// In MaterialType order, so kMaterialSchemas[int(type)] is the schema of type.
inline const MaterialSchema kMaterialSchemas[] = {
    {"diffuse", MaterialType::Diffuse, "albedo", std::nullopt, false, false, false},
    {"emitter", MaterialType::Emitter, nullptr, std::nullopt, false, false, true},
    {"diffuse_transmission", MaterialType::DiffuseTransmission, "transmittance", std::nullopt, false, false, false},
    {"mirror", MaterialType::Mirror, "reflectance", glm::vec3(1.0f), false, false, false},
    {"specular_transmission", MaterialType::SpecularTransmission, "transmittance", glm::vec3(1.0f), true, false, false},
    {"glass", MaterialType::Glass, "tint", glm::vec3(1.0f), true, false, false},
    {"metal", MaterialType::Metal, "reflectance", std::nullopt, false, true, false},
    {"plastic", MaterialType::Plastic, "albedo", std::nullopt, true, true, false},
    {"principled", MaterialType::Principled, "base_color", glm::vec3(1.0f), true, true, false},
    // A volume, not a surface: no colour, no emission (docs/volumes.md).
    {"medium", MaterialType::Medium, nullptr, std::nullopt, false, false, false},
};

inline const MaterialSchema& materialSchema(MaterialType type) {
    return kMaterialSchemas[static_cast<int>(type)];
}

// nullptr when no type has that name.
inline const MaterialSchema* findMaterialSchema(std::string_view name) { return findSchemaNamed(kMaterialSchemas, name); }

} // namespace ptview
