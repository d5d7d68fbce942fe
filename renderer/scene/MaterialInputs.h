#pragma once
// A material's inputs, one row each: its key in a scene file, the member of Material it sets, its
// range, its texture slot, which types take it and when the writer writes it. The loader (a loop
// over the rows), the writer, the glTF override writer, the input copier (copyMaterialInput) and
// the Materials panel all read this one table; MaterialSchema.h says what each type has.

#include <ptview/scene/MaterialSchema.h>
#include <ptview/scene/SceneRanges.h>

#include <algorithm>
#include <string_view>
#include <vector>

namespace ptview {

// What an input's value is, and so how it is read and written.
enum class InputValue {
    Vector,   // Material::*vector, each component in range
    Number,   // Material::*number, in range
    AlphaMode, // Material::alphaMode, by alphaModeNames()
    Strength, // a number the emission read before it is multiplied by; stored nowhere else
    Interior, // {"sigma_a", "sigma_s", "g"}: Material's medium fields, and hasInterior
};

// When the writer writes an input of a type that takes it.
enum class InputWrite {
    Always,
    UnlessDefault, // when the value differs from a default Material's, or a texture is there
    WithTexture,   // only with a texture: the factor alone would say nothing, so a bare one is refused
    Never,         // emission_strength: the emission it scaled holds it
};

struct MaterialInput {
    const char* key; // in the scene file; nullptr: the type's colour (MaterialSchema::colorKey)
    bool (*takenBy)(const MaterialSchema&);
    InputValue value;
    glm::vec3 Material::*vector; // InputValue::Vector
    float Material::*number;     // InputValue::Number
    const SceneRange* range;     // nullptr: AlphaMode
    TextureSlot Material::*slot; // nullptr: never textured
    bool required;               // in a material of the scene's own (an override may leave anything out)
    InputWrite write;
    // The loader reads inputs in this order (not the table's), which decides which of several
    // errors a file is told of first: the emission first, as emission_strength scales it.
    int readRank;
    const char* panelLabel; // the Materials panel's slider, for a Number; nullptr: none
};

namespace materialInputTakers {
inline bool emitter(const MaterialSchema& s) { return s.radianceRequired; }
inline bool surface(const MaterialSchema& s) { return !s.radianceRequired && s.type != MaterialType::Medium; }
inline bool medium(const MaterialSchema& s) { return s.type == MaterialType::Medium; }
// The models that refract, whose closed shape may hold a medium.
inline bool refracting(const MaterialSchema& s) {
    return s.type == MaterialType::SpecularTransmission || s.type == MaterialType::Glass || s.type == MaterialType::Principled;
}
inline bool colored(const MaterialSchema& s) { return s.colorKey != nullptr; }
inline bool withIor(const MaterialSchema& s) { return s.hasIor; }
inline bool withRoughness(const MaterialSchema& s) { return s.hasRoughness; }
inline bool principled(const MaterialSchema& s) { return s.type == MaterialType::Principled; }
} // namespace materialInputTakers

// In the order of a material's keys in a file: the writer's, and that of the loader's list of them.
inline const MaterialInput kMaterialInputs[] = {
    {"radiance", materialInputTakers::emitter, InputValue::Vector, &Material::radiance, nullptr, &ranges::kRadiance,
     nullptr, true, InputWrite::Always, 0, nullptr},
    {nullptr, materialInputTakers::colored, InputValue::Vector, &Material::color, nullptr, &ranges::kColor,
     &Material::baseColorTexture, true, InputWrite::Always, 1, nullptr},
    {"ior", materialInputTakers::withIor, InputValue::Number, nullptr, &Material::ior, &ranges::kIor, nullptr, false,
     InputWrite::Always, 2, "ior"},
    {"roughness", materialInputTakers::withRoughness, InputValue::Number, nullptr, &Material::roughness,
     &ranges::kRoughness, &Material::roughnessTexture, false, InputWrite::Always, 3, "roughness"},
    {"emission", materialInputTakers::surface, InputValue::Vector, &Material::radiance, nullptr, &ranges::kRadiance,
     &Material::emissionTexture, false, InputWrite::UnlessDefault, 0, nullptr},
    {"metallic", materialInputTakers::principled, InputValue::Number, nullptr, &Material::metallic, &ranges::kMetallic,
     &Material::metallicTexture, false, InputWrite::Always, 4, "metallic"},
    {"transmission", materialInputTakers::principled, InputValue::Number, nullptr, &Material::transmission,
     &ranges::kTransmission, nullptr, false, InputWrite::UnlessDefault, 5, "transmission"},
    {"alpha", materialInputTakers::principled, InputValue::Number, nullptr, &Material::alpha, &ranges::kAlpha, nullptr,
     false, InputWrite::UnlessDefault, 6, "alpha"},
    {"alpha_mode", materialInputTakers::principled, InputValue::AlphaMode, nullptr, nullptr, nullptr, nullptr, false,
     InputWrite::UnlessDefault, 9, nullptr},
    {"alpha_cutoff", materialInputTakers::principled, InputValue::Number, nullptr, &Material::alphaCutoff,
     &ranges::kAlphaCutoff, nullptr, false, InputWrite::UnlessDefault, 7, nullptr},
    {"emission_strength", materialInputTakers::principled, InputValue::Strength, nullptr, nullptr, &ranges::kRadiance,
     nullptr, false, InputWrite::Never, 10, nullptr},
    // glTF's normalTexture.scale is the factor of the normal map.
    {"normal_map", materialInputTakers::principled, InputValue::Number, nullptr, &Material::normalScale,
     &ranges::kNormalScale, &Material::normalTexture, false, InputWrite::WithTexture, 8, "normal scale"},
    {"sigma_a", materialInputTakers::medium, InputValue::Vector, &Material::sigmaA, nullptr, &ranges::kMediumCoefficient,
     nullptr, false, InputWrite::Always, 11, nullptr},
    {"sigma_s", materialInputTakers::medium, InputValue::Vector, &Material::sigmaS, nullptr, &ranges::kMediumCoefficient,
     nullptr, false, InputWrite::Always, 12, nullptr},
    {"g", materialInputTakers::medium, InputValue::Number, nullptr, &Material::g, &ranges::kPhaseAsymmetry, nullptr, false,
     InputWrite::Always, 13, "g"},
    // The same three of a medium inside the shape (KHR_materials_volume); absent: a thin surface.
    {"interior", materialInputTakers::refracting, InputValue::Interior, nullptr, nullptr, nullptr, nullptr, false,
     InputWrite::UnlessDefault, 14, nullptr},
};

// The input's key in a material of this type.
inline const char* materialInputKey(const MaterialInput& input, const MaterialSchema& schema) {
    return input.key ? input.key : schema.colorKey;
}

// A colour is required unless the type has a default for it.
inline bool materialInputRequired(const MaterialInput& input, const MaterialSchema& schema) {
    return input.key ? input.required : !schema.colorDefault;
}

// The input of this type under `key`; nullptr when the type has none ("type" is no input).
inline const MaterialInput* findMaterialInput(const MaterialSchema& schema, std::string_view key) {
    for (const MaterialInput& input : kMaterialInputs)
        if (input.takenBy(schema) && key == materialInputKey(input, schema)) return &input;
    return nullptr;
}

// The inputs in the order the loader reads them (readRank).
inline const std::vector<const MaterialInput*>& materialInputsInReadOrder() {
    static const std::vector<const MaterialInput*> order = [] {
        std::vector<const MaterialInput*> inputs;
        for (const MaterialInput& input : kMaterialInputs) inputs.push_back(&input);
        std::stable_sort(inputs.begin(), inputs.end(),
                         [](const MaterialInput* a, const MaterialInput* b) { return a->readRank < b->readRank; });
        return inputs;
    }();
    return order;
}

// Every key a material of this type may have, in the order the loader lists them.
inline std::vector<const char*> materialKeys(const MaterialSchema& schema) {
    std::vector<const char*> keys = {"type"};
    for (const MaterialInput& input : kMaterialInputs)
        if (input.takenBy(schema)) keys.push_back(materialInputKey(input, schema));
    return keys;
}

// Every key some material type has, each once, in the order of first appearance in the table:
// the keys allowed while a material's type is not known.
inline std::vector<const char*> anyMaterialKeys() {
    std::vector<const char*> keys;
    for (const MaterialSchema& schema : kMaterialSchemas) appendNewKeys(keys, materialKeys(schema));
    return keys;
}

// The fields of a material that one input sets, copied from `from` to `to`: its value and its
// texture slot (emission_strength none: it scales the emission as read).
inline void copyMaterialInput(const MaterialInput& input, const Material& from, Material& to) {
    switch (input.value) {
    case InputValue::Vector: to.*input.vector = from.*input.vector; break;
    case InputValue::Number: to.*input.number = from.*input.number; break;
    case InputValue::AlphaMode: to.alphaMode = from.alphaMode; break;
    case InputValue::Strength: break;
    case InputValue::Interior:
        to.hasInterior = from.hasInterior;
        to.sigmaA = from.sigmaA;
        to.sigmaS = from.sigmaS;
        to.g = from.g;
        break;
    }
    if (input.slot) to.*input.slot = from.*input.slot;
}

// The same for one key of `schema`, "type" included. An override of a glTF material keeps the
// file's value of a key it leaves out this way, and the writer finds the keys an override must
// hold by which copies change something.
inline void copyMaterialInput(const MaterialSchema& schema, std::string_view key, const Material& from, Material& to) {
    if (key == "type") to.type = from.type;
    else if (const MaterialInput* input = findMaterialInput(schema, key)) copyMaterialInput(*input, from, to);
}

// Whether the writer writes the input of this material (of a type that takes it).
inline bool materialInputWritten(const MaterialInput& input, const Material& material) {
    const bool textured = input.slot && (material.*input.slot).used();
    const Material defaults;
    switch (input.write) {
    case InputWrite::Always: return true;
    case InputWrite::WithTexture: return textured;
    case InputWrite::Never: return false;
    case InputWrite::UnlessDefault: break;
    }
    switch (input.value) {
    case InputValue::Vector: return textured || material.*input.vector != defaults.*input.vector;
    case InputValue::Number: return textured || material.*input.number != defaults.*input.number;
    case InputValue::AlphaMode: return material.alphaMode != defaults.alphaMode;
    case InputValue::Strength: break;
    case InputValue::Interior: return material.hasInterior;
    }
    return false;
}

} // namespace ptview
