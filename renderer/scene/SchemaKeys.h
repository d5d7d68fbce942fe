#pragma once
// Helpers the per-kind key tables (ShapeSchema.h, LightSchema.h, MaterialSchema.h) share: the
// union of their key lists and the "a, b or c" list of their type names.

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace ptview {

// Appends each of more's keys that keys does not hold yet, keeping first-appearance order.
template <typename Keys>
void appendNewKeys(std::vector<const char*>& keys, const Keys& more) {
    for (const char* key : more)
        if (std::none_of(keys.begin(), keys.end(), [key](const char* known) { return std::string_view(known) == key; }))
            keys.push_back(key);
}

// The schema of a table whose `name` is this one; nullptr when none is.
template <typename Schema, std::size_t N>
const Schema* findSchemaNamed(const Schema (&schemas)[N], std::string_view name) {
    for (const Schema& schema : schemas)
        if (name == schema.name) return &schema;
    return nullptr;
}

// "sphere, quad or box": the names of a schema table, for the message about an unknown type.
template <typename Schema, std::size_t N>
std::string schemaNameList(const Schema (&schemas)[N]) {
    std::string list;
    for (std::size_t i = 0; i < N; ++i) {
        if (i > 0) list += i + 1 < N ? ", " : " or ";
        list += schemas[i].name;
    }
    return list;
}

} // namespace ptview
