#pragma once
// Which keys each shape type takes in a scene file. The loader (its unknown-key errors and its
// list of types) and the writer (the type names) read this one table, so a shape cannot gain a
// key or a type in one of them and not the other.

#include <ptview/scene/Scene.h>
#include <ptview/scene/SchemaKeys.h>

#include <iterator>
#include <string_view>
#include <vector>

namespace ptview {

// Every shape, whatever its type, may have a "name", has a "type" and may have a "transform"; in
// a file they come first, first and last, so a type's keys are only what lies between.
struct ShapeSchema {
    const char* name; // the JSON "type"
    ShapeType type;
    std::vector<const char*> keys; // in the order the loader lists them
};

inline const char* const kShapeLeadingKeys[] = {"name", "type"};
inline const char* const kShapeTrailingKey = "transform";

// In ShapeType order, so kShapeSchemas[int(type)] is the schema of type.
inline const ShapeSchema kShapeSchemas[] = {
    {"sphere", ShapeType::Sphere, {"material", "center", "radius"}},
    {"quad", ShapeType::Quad, {"material", "center", "u", "v"}},
    {"box", ShapeType::Box, {"material", "center", "half_size", "rotation"}},
    {"disk", ShapeType::Disk, {"material", "center", "normal", "radius"}},
    {"mesh", ShapeType::Mesh, {"mesh", "material", "materials"}},
};

inline const ShapeSchema& shapeSchema(ShapeType type) {
    return kShapeSchemas[static_cast<int>(type)];
}

// nullptr when no type has that name.
inline const ShapeSchema* findShapeSchema(std::string_view name) { return findSchemaNamed(kShapeSchemas, name); }

// Every key a shape of this type may have, in the order the loader lists them.
inline std::vector<const char*> shapeKeys(const ShapeSchema& schema) {
    std::vector<const char*> keys(std::begin(kShapeLeadingKeys), std::end(kShapeLeadingKeys));
    keys.insert(keys.end(), schema.keys.begin(), schema.keys.end());
    keys.push_back(kShapeTrailingKey);
    return keys;
}

// Every key some shape type has, each once, in the order of first appearance in the table: the
// keys allowed while a shape's type is not known.
inline std::vector<const char*> anyShapeKeys() {
    std::vector<const char*> keys(std::begin(kShapeLeadingKeys), std::end(kShapeLeadingKeys));
    for (const ShapeSchema& schema : kShapeSchemas) appendNewKeys(keys, schema.keys);
    keys.push_back(kShapeTrailingKey);
    return keys;
}

} // namespace ptview
