#pragma once
// Which keys each light type takes in a scene file. The loader (its unknown-key errors and its
// list of types) and the writer (the type names) read this one table, like ShapeSchema.h.

#include <ptview/scene/Scene.h>
#include <ptview/scene/SchemaKeys.h>

#include <iterator>
#include <string_view>
#include <vector>

namespace ptview {

// Every light may have a "name" and has a "type", first in a file; a type's keys follow.
struct LightSchema {
    const char* name; // the JSON "type"
    LightType type;
    std::vector<const char*> keys; // in the order the loader lists them
};

inline const char* const kLightLeadingKeys[] = {"name", "type"};

// In LightType order, so kLightSchemas[int(type)] is the schema of type.
inline const LightSchema kLightSchemas[] = {
    {"point", LightType::Point, {"position", "intensity"}},
    {"spot", LightType::Spot, {"position", "direction", "intensity", "inner_deg", "outer_deg"}},
    {"directional", LightType::Directional, {"direction", "intensity"}},
};

inline const LightSchema& lightSchema(LightType type) {
    return kLightSchemas[static_cast<int>(type)];
}

// nullptr when no type has that name.
inline const LightSchema* findLightSchema(std::string_view name) { return findSchemaNamed(kLightSchemas, name); }

// Every key a light of this type may have, in the order the loader lists them.
inline std::vector<const char*> lightKeys(const LightSchema& schema) {
    std::vector<const char*> keys(std::begin(kLightLeadingKeys), std::end(kLightLeadingKeys));
    keys.insert(keys.end(), schema.keys.begin(), schema.keys.end());
    return keys;
}

// Every key some light type has, each once, in the order of first appearance in the table.
inline std::vector<const char*> anyLightKeys() {
    std::vector<const char*> keys(std::begin(kLightLeadingKeys), std::end(kLightLeadingKeys));
    for (const LightSchema& schema : kLightSchemas) appendNewKeys(keys, schema.keys);
    return keys;
}

} // namespace ptview
