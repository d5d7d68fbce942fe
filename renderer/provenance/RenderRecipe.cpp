#include <ptview/provenance/RenderRecipe.h>

#include <ptview/settings/SettingRanges.h>

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
    // What a file without the key meant, where that is not RenderRecipe's default (a default that
    // changed); empty: the default.
    std::function<void(RenderRecipe&)> absent = {};
};

// A value of the file as a message quotes it: JSON (so controls are escaped), cut at 40 characters
// (a file may hold a megabyte where a number belongs).
std::string quotedValue(const Json& j) {
    constexpr std::size_t kLongest = 40;
    std::string text = j.dump(-1, ' ', false, Json::error_handler_t::replace);
    return text.size() <= kLongest ? text : text.substr(0, kLongest) + "... (" + std::to_string(text.size()) + " characters)";
}

// A number of `range` (SettingRanges.h, the command line's bounds): an integer field takes only a
// JSON integer, a float field the float it rounds to. A file may come from anyone, so a value the
// command line would refuse is refused here too, not wrapped (-1 as a seed) or truncated (16.7).
template <typename Value>
Value numberInRange(const Json& j, const NumberRange& range) {
    const bool integer = std::is_integral_v<Value>;
    const bool typeFits = integer ? j.is_number_integer() : j.is_number();
    double value = 0.0;
    if (typeFits) value = j.is_number_unsigned() ? double(j.get<std::uint64_t>())
                          : j.is_number_integer() ? double(j.get<std::int64_t>())
                                                  : j.get<double>();
    if (!integer) value = static_cast<float>(value); // as stored
    if (!typeFits || !range.containsAsStored(value))
        throw RecipeError(std::string("expected ") + range.expected() + " (the " + range.quantity + "), got " + quotedValue(j));
    return static_cast<Value>(value);
}

// A number in its range. `member(recipe)` names the field.
template <typename Member>
RecipeField numberField(const char* key, const NumberRange& range, Member member) {
    return {key, [member](const RenderRecipe& r) { return Json(member(const_cast<RenderRecipe&>(r))); },
            [member, &range](const Json& j, RenderRecipe& r) {
                auto& value = member(r);
                value = numberInRange<std::decay_t<decltype(value)>>(j, range);
            }};
}

// A bool, stored as JSON does it.
template <typename Member>
RecipeField boolField(const char* key, Member member) {
    return {key, [member](const RenderRecipe& r) { return Json(member(const_cast<RenderRecipe&>(r))); },
            [member](const Json& j, RenderRecipe& r) { member(r) = j.get<bool>(); }};
}

// An enum, by its name in its table (the names users type, which never change).
template <typename Table, typename Member>
RecipeField enumField(const char* key, const Table& (*table)(), Member member) {
    return {key, [table, member](const RenderRecipe& r) { return Json(table().name(member(const_cast<RenderRecipe&>(r)))); },
            [table, member](const Json& j, RenderRecipe& r) {
                const auto value = table().parse(j.get<std::string>());
                if (!value) throw RecipeError("unknown name " + quotedValue(j));
                member(r) = *value;
            }};
}

// A string of at most 4096 bytes (a path or a name).
template <typename Member>
RecipeField stringField(const char* key, Member member) {
    return {key, [member](const RenderRecipe& r) { return Json(member(const_cast<RenderRecipe&>(r))); },
            [member](const Json& j, RenderRecipe& r) {
                std::string value = j.get<std::string>();
                if (value.size() > 4096) throw RecipeError("a string of " + std::to_string(value.size()) + " bytes, more than 4096");
                member(r) = std::move(value);
            }};
}

// An optional number in its range: null when absent (e.g. no --clamp).
template <typename Member>
RecipeField optionalNumberField(const char* key, const NumberRange& range, Member member) {
    return {key,
            [member](const RenderRecipe& r) {
                const auto& value = member(const_cast<RenderRecipe&>(r));
                return value ? Json(*value) : Json(nullptr);
            },
            [member, &range](const Json& j, RenderRecipe& r) {
                auto& value = member(r);
                if (j.is_null()) value.reset();
                else value = numberInRange<typename std::decay_t<decltype(value)>::value_type>(j, range);
            }};
}

RecipeField withAbsent(RecipeField field, std::function<void(RenderRecipe&)> absent) {
    field.absent = std::move(absent);
    return field;
}

const std::vector<RecipeField>& recipeFields() {
    // One line per field: a new setting is a new line here.
    static const std::vector<RecipeField> fields = {
        enumField("integrator", integratorNames, [](RenderRecipe& r) -> auto& { return r.settings.integrator; }),
        enumField("sampler", samplerModeNames, [](RenderRecipe& r) -> auto& { return r.settings.sampler; }),
        numberField("max_depth", settingRanges::kMaxDepth, [](RenderRecipe& r) -> auto& { return r.settings.maxDepth; }),
        numberField("seed", settingRanges::kSeed, [](RenderRecipe& r) -> auto& { return r.settings.seed; }),
        numberField("sample_budget", settingRanges::kSampleBudget, [](RenderRecipe& r) -> auto& { return r.settings.sampleBudget; }),
        enumField("view", debugViewNames, [](RenderRecipe& r) -> auto& { return r.settings.debugView; }),
        optionalNumberField("radiance_clamp", settingRanges::kRadianceClamp, [](RenderRecipe& r) -> auto& { return r.settings.radianceClamp; }),
        numberField("spp", settingRanges::kSamplesPerPixel, [](RenderRecipe& r) -> auto& { return r.samplesPerPixel; }),
        numberField("width", settingRanges::kImageSide, [](RenderRecipe& r) -> auto& { return r.size.x; }),
        numberField("height", settingRanges::kImageSide, [](RenderRecipe& r) -> auto& { return r.size.y; }),
        enumField("backend", backendNames, [](RenderRecipe& r) -> auto& { return r.backend; }),
        boolField("all_features", [](RenderRecipe& r) -> auto& { return r.allFeatures; }),
        numberField("exposure_stops", settingRanges::kExposure, [](RenderRecipe& r) -> auto& { return r.display.exposureStops; }),
        enumField("tone_mapper", toneMapperNames, [](RenderRecipe& r) -> auto& { return r.display.toneMapper; }),
        withAbsent(enumField("display_transfer", displayTransferNames, [](RenderRecipe& r) -> auto& { return r.display.transfer; }),
                   // Files from before the sRGB curve were encoded with gamma 2.2.
                   [](RenderRecipe& r) { r.display.transfer = DisplayTransfer::Gamma22; }),
        stringField("ocio_config", [](RenderRecipe& r) -> auto& { return r.ocio.config; }),
        stringField("ocio_display", [](RenderRecipe& r) -> auto& { return r.ocio.display; }),
        stringField("ocio_view", [](RenderRecipe& r) -> auto& { return r.ocio.view; }),
        boolField("highlight_non_finite", [](RenderRecipe& r) -> auto& { return r.display.highlightNonFinite; }),
        boolField("denoise", [](RenderRecipe& r) -> auto& { return r.denoise.enabled; }),
        // Files from before there was a choice were denoised by the à-trous filter, the table's first.
        enumField("denoise_algorithm", denoiseAlgorithmNames, [](RenderRecipe& r) -> auto& { return r.denoise.algorithm; }),
        numberField("denoise_iterations", settingRanges::kDenoiseIterations, [](RenderRecipe& r) -> auto& { return r.denoise.iterations; }),
        numberField("denoise_strength", settingRanges::kDenoiseStrength, [](RenderRecipe& r) -> auto& { return r.denoise.strength; }),
        optionalNumberField("noise_threshold", settingRanges::kNoiseThreshold, [](RenderRecipe& r) -> auto& { return r.noiseThreshold; }),
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
    // The settings are one object of plain values. Deeper nesting is refused while it is read:
    // ordered_json copies an object's members, recursively, each time the object grows, and
    // dump() recurses too, so 100000 nested arrays in a PNG overflowed the stack.
    constexpr int kMaxNesting = 64;
    const Json::parser_callback_t boundNesting = [&where](int depth, Json::parse_event_t event, Json&) {
        const bool opens = event == Json::parse_event_t::object_start || event == Json::parse_event_t::array_start;
        if (opens && depth >= kMaxNesting)
            throw RecipeError(where + ": the settings nest arrays and objects deeper than " +
                              std::to_string(kMaxNesting) + " levels");
        return true;
    };
    Json json;
    try {
        json = Json::parse(text, boundNesting);
    } catch (const Json::exception& e) {
        throw RecipeError(where + ": the settings are not JSON: " + e.what());
    }
    if (!json.is_object()) throw RecipeError(where + ": the settings are not a JSON object");
    RenderRecipe recipe;
    for (const RecipeField& field : recipeFields()) {
        auto it = json.find(field.key);
        if (it == json.end()) {
            if (field.absent) field.absent(recipe);
            continue;
        }
        try {
            field.read(*it, recipe);
        } catch (const Json::exception& e) {
            throw RecipeError(where + ": settings \"" + field.key + "\": " + e.what());
        } catch (const RecipeError& e) {
            throw RecipeError(where + ": settings \"" + field.key + "\": " + e.what());
        }
    }
    // Keys every ptview that wrote settings wrote: without them there is no image to render.
    for (const char* key : {"spp", "width", "height"})
        if (json.find(key) == json.end()) throw RecipeError(where + ": settings lack \"" + key + "\"");
    return recipe;
}

} // namespace ptview
