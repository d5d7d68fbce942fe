#include "RenderRecipe.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <type_traits>
#include <vector>

namespace ptview {
namespace {

using Json = nlohmann::ordered_json; // keys in the table's order

struct RecipeField {
    const char* key;
    std::function<Json(const RenderRecipe&)> write;
    std::function<void(const Json&, RenderRecipe&)> read; // throws nlohmann's or RecipeError
};

// A number, a bool or a size, stored as JSON does it. `member(recipe)` names the field.
template <typename Member>
RecipeField valueField(const char* key, Member member) {
    return {key, [member](const RenderRecipe& r) { return Json(member(const_cast<RenderRecipe&>(r))); },
            [member](const Json& j, RenderRecipe& r) {
                auto& value = member(r);
                value = j.get<std::decay_t<decltype(value)>>();
            }};
}

// An enum, by its name in its table (the names users type, which never change).
template <typename Table, typename Member>
RecipeField enumField(const char* key, const Table& (*table)(), Member member) {
    return {key, [table, member](const RenderRecipe& r) { return Json(table().name(member(const_cast<RenderRecipe&>(r)))); },
            [table, member, key](const Json& j, RenderRecipe& r) {
                const auto value = table().parse(j.get<std::string>());
                if (!value) throw RecipeError(std::string("\"") + key + "\": unknown name \"" + j.get<std::string>() + "\"");
                member(r) = *value;
            }};
}

// An optional number: null when absent (e.g. no --clamp).
template <typename Member>
RecipeField optionalNumberField(const char* key, Member member) {
    return {key,
            [member](const RenderRecipe& r) {
                const auto& value = member(const_cast<RenderRecipe&>(r));
                return value ? Json(*value) : Json(nullptr);
            },
            [member](const Json& j, RenderRecipe& r) {
                auto& value = member(r);
                if (j.is_null()) value.reset();
                else value = j.get<typename std::decay_t<decltype(value)>::value_type>();
            }};
}

const std::vector<RecipeField>& recipeFields() {
    // One line per field: a new setting is a new line here.
    static const std::vector<RecipeField> fields = {
        enumField("integrator", integratorNames, [](RenderRecipe& r) -> auto& { return r.settings.integrator; }),
        enumField("sampler", samplerModeNames, [](RenderRecipe& r) -> auto& { return r.settings.sampler; }),
        valueField("max_depth", [](RenderRecipe& r) -> auto& { return r.settings.maxDepth; }),
        valueField("seed", [](RenderRecipe& r) -> auto& { return r.settings.seed; }),
        valueField("sample_budget", [](RenderRecipe& r) -> auto& { return r.settings.sampleBudget; }),
        enumField("view", debugViewNames, [](RenderRecipe& r) -> auto& { return r.settings.debugView; }),
        optionalNumberField("radiance_clamp", [](RenderRecipe& r) -> auto& { return r.settings.radianceClamp; }),
        valueField("spp", [](RenderRecipe& r) -> auto& { return r.samplesPerPixel; }),
        valueField("width", [](RenderRecipe& r) -> auto& { return r.size.x; }),
        valueField("height", [](RenderRecipe& r) -> auto& { return r.size.y; }),
        enumField("backend", backendNames, [](RenderRecipe& r) -> auto& { return r.backend; }),
        valueField("all_features", [](RenderRecipe& r) -> auto& { return r.allFeatures; }),
        valueField("exposure_stops", [](RenderRecipe& r) -> auto& { return r.display.exposureStops; }),
        enumField("tone_mapper", toneMapperNames, [](RenderRecipe& r) -> auto& { return r.display.toneMapper; }),
        valueField("highlight_non_finite", [](RenderRecipe& r) -> auto& { return r.display.highlightNonFinite; }),
    };
    return fields;
}

} // namespace

std::string recipeToJson(const RenderRecipe& recipe) {
    Json json = Json::object();
    for (const RecipeField& field : recipeFields()) json[field.key] = field.write(recipe);
    return json.dump(2);
}

RenderRecipe recipeFromJson(const std::string& text, const std::string& where) {
    Json json;
    try {
        json = Json::parse(text);
    } catch (const Json::exception& e) {
        throw RecipeError(where + ": the settings are not JSON: " + e.what());
    }
    if (!json.is_object()) throw RecipeError(where + ": the settings are not a JSON object");
    RenderRecipe recipe;
    for (const RecipeField& field : recipeFields()) {
        auto it = json.find(field.key);
        if (it == json.end()) continue;
        try {
            field.read(*it, recipe);
        } catch (const Json::exception& e) {
            throw RecipeError(where + ": settings \"" + field.key + "\": " + e.what());
        } catch (const RecipeError& e) {
            throw RecipeError(where + ": settings " + e.what());
        }
    }
    return recipe;
}

} // namespace ptview
