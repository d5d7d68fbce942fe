#pragma once
// The readers of a scene file's values: each checks one value (its type, its range, the keys of an
// object) and fails with its JSON pointer (SceneJson.h), so that every rejection names its place.

#include <ptview/settings/EnumTable.h>
#include <ptview/scene/SceneJson.h>
#include <ptview/scene/SceneRanges.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

namespace ptview::sceneFile {

// Bounds that keep every image finite. Any float fits the file, but the renderer multiplies what
// it reads: a quad's plane test takes the product of three lengths (the distance to it and its
// two edges), a sphere's the square of one, and an emitter's radiance is summed over up to 2^24
// samples and divided by densities that may be 1e-6 or less. A coordinate or a length of 1e9 m
// (a million km; scenes here span 1e-3 to 1e4 m) keeps a product of three at 1e27, and a radiance
// of 1e9 keeps 2^24 samples of it over such a density at 1e22, both far below float's 3.4e38.
// Before these bounds a sphere of radius 1e38 scaled by 1e5 loaded with an infinite radius, and an
// environment intensity of 3e38 made half the pixels NaN or Inf.
constexpr float kMaxExtent = kMaxSceneExtent;     // SceneRanges.h: |coordinate|, radius, half size, |u|, |v|
constexpr float kMaxRadiance = kMaxSceneRadiance; // SceneRanges.h: radiance, emission, light and environment intensity

// Fails at the first key of `object` that `allowed` lacks, listing those it has.
template <typename Names>
void checkKeys(const Json& object, const Pointer& at, const Names& allowed) {
    for (auto it = object.begin(); it != object.end(); ++it) {
        bool known = std::any_of(allowed.begin(), allowed.end(),
                                 [&](const char* name) { return it.key() == name; });
        if (!known) {
            std::string list;
            for (const char* name : allowed)
                list += (list.empty() ? "" : ", ") + std::string(name);
            fail(at / it.key(), "unknown key (expected one of: " + list + ")");
        }
    }
}

void checkKeys(const Json& object, const Pointer& at, std::initializer_list<const char*> allowed);
// Which keys are allowed depends on "type", so it is read first (SceneFileReaders.cpp).
void requireType(const Json& object, const Pointer& at, const std::vector<const char*>& anyTypeKeys);

const Json& requireObject(const Json& value, const Pointer& at);
const Json& requireKey(const Json& object, const Pointer& at, const char* key);
const Json* optionalKey(const Json& object, const char* key); // nullptr: absent
std::string readString(const Json& value, const Pointer& at);
float readNumber(const Json& value, const Pointer& at); // a finite float

// [x, y, z] where every component must satisfy isValid, which `expected` describes.
template <typename Predicate>
glm::vec3 readVec3(const Json& value, const Pointer& at, Predicate isValid, const char* expected) {
    if (!value.is_array() || value.size() != 3)
        fail(at, "expected an array of 3 numbers");
    glm::vec3 v(0.0f);
    for (int i = 0; i < 3; ++i) {
        Pointer componentAt = at / i;
        v[i] = readNumber(value[i], componentAt);
        if (!isValid(v[i]))
            fail(componentAt, std::string("expected ") + expected);
    }
    return v;
}

glm::vec3 readVec3(const Json& value, const Pointer& at);
glm::vec2 readVec2(const Json& value, const Pointer& at);
// A number, or each component, within its range of SceneRanges.h.
float readInRange(const Json& value, const Pointer& at, const SceneRange& range);
glm::vec3 readVec3InRange(const Json& value, const Pointer& at, const SceneRange& range);
glm::vec3 readPosition(const Json& value, const Pointer& at);    // each coordinate within kMaxExtent
float readLength(const Json& value, const Pointer& at);          // in (0, kMaxExtent]
glm::vec3 readNonzeroVec3(const Json& value, const Pointer& at);
glm::vec3 readEdge(const Json& value, const Pointer& at);        // nonzero, of length at most kMaxExtent
glm::vec3 readDirection(const Json& value, const Pointer& at);   // nonzero, stored at unit length
glm::ivec2 readResolution(const Json& value, const Pointer& at); // [width, height]

// A value of `names` by its name; `what` names the kind in the message ("wrap mode").
template <typename E>
E readEnum(const Json& value, const Pointer& at, const EnumTable<E>& names, const char* what) {
    std::string name = readString(value, at);
    if (std::optional<E> known = names.parse(name)) return *known;
    fail(at, std::string("unknown ") + what + " \"" + name + "\" (expected one of: " + names.nameList() + ")");
}

// "%g" of a bound, for messages.
std::string boundText(float bound);
// Parallel within float noise: the sine of the angle between them is below 1e-6.
bool areParallel(const glm::vec3& a, const glm::vec3& b);

} // namespace ptview::sceneFile
