#include <ptview/scene/SceneFileReaders.h>

#include <ptview/scene/Scene.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>

namespace ptview::sceneFile {

const Json& requireObject(const Json& value, const Pointer& at) {
    if (!value.is_object())
        fail(at, "expected an object, got " + describe(value));
    return value;
}

const Json& requireKey(const Json& object, const Pointer& at, const char* key) {
    auto it = object.find(key);
    if (it == object.end())
        fail(at / key, "missing required key");
    return *it;
}

const Json* optionalKey(const Json& object, const char* key) {
    auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

std::string readString(const Json& value, const Pointer& at) {
    if (!value.is_string())
        fail(at, "expected a string, got " + describe(value));
    return value.get<std::string>();
}

// The parser already rejects numbers that overflow a double; this catches those that fit a
// double but not the float the renderer stores.
float readNumber(const Json& value, const Pointer& at) {
    if (!value.is_number())
        fail(at, "expected a number, got " + describe(value));
    double number = value.get<double>();
    if (!std::isfinite(number) || std::abs(number) > std::numeric_limits<float>::max())
        fail(at, "number " + value.dump() + " is out of range");
    return static_cast<float>(number);
}

glm::vec3 readVec3(const Json& value, const Pointer& at) {
    return readVec3(value, at, [](float) { return true; }, "a number");
}

// A number, or each component, within its range of SceneRanges.h.
float readInRange(const Json& value, const Pointer& at, const SceneRange& range) {
    float number = readNumber(value, at);
    if (!range.contains(number)) fail(at, "expected " + range.expected());
    return number;
}

glm::vec3 readVec3InRange(const Json& value, const Pointer& at, const SceneRange& range) {
    return readVec3(value, at, [&range](float c) { return range.contains(c); }, range.expected().c_str());
}

std::string boundText(float bound) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", static_cast<double>(bound));
    return text;
}

// A point in space: each coordinate within kMaxExtent of the origin.
glm::vec3 readPosition(const Json& value, const Pointer& at) {
    return readVec3(value, at, [](float c) { return std::abs(c) <= kMaxExtent; },
                    ("a coordinate in [-" + boundText(kMaxExtent) + ", " + boundText(kMaxExtent) + "] (metres)").c_str());
}

// A length in (0, kMaxExtent].
float readLength(const Json& value, const Pointer& at) {
    float number = readNumber(value, at);
    if (!(number > 0.0f && number <= kMaxExtent))
        fail(at, "expected a positive number at most " + boundText(kMaxExtent) + " (metres)");
    return number;
}

glm::vec3 readNonzeroVec3(const Json& value, const Pointer& at) {
    glm::vec3 v = readVec3(value, at);
    if (v == glm::vec3(0.0f))
        fail(at, "expected a nonzero vector");
    return v;
}

// An edge vector (a quad's u or v): nonzero, of length at most kMaxExtent, taken in double so that
// a length of 3e38 is not an infinity that later reads as "parallel".
glm::vec3 readEdge(const Json& value, const Pointer& at) {
    glm::vec3 v = readNonzeroVec3(value, at);
    const double length = glm::length(glm::dvec3(v));
    if (!(length <= kMaxExtent))
        fail(at, "length " + boundText(static_cast<float>(std::min(length, 3.4e38))) + " is above " +
                     boundText(kMaxExtent) + " (metres)");
    return v;
}

// Parallel within float noise: the sine of the angle between them is below 1e-6.
bool areParallel(const glm::vec3& a, const glm::vec3& b) {
    return glm::length(glm::cross(a, b)) <= 1e-6f * glm::length(a) * glm::length(b);
}

// A nonzero vector, stored at unit length. One that is unit already, as far as a float can tell,
// is kept as written: normalizing it again could move it by an ulp, and then a file the writer
// wrote (which holds the stored unit vector) would not read back bit for bit.
glm::vec3 readDirection(const Json& value, const Pointer& at) {
    glm::vec3 v = readNonzeroVec3(value, at);
    // A direction written at unit length is kept as written, so a scene saved again reads the same.
    if (std::abs(glm::length(glm::dvec3(v)) - 1.0) <= 1e-6) return v;
    return unitDirection(v);
}

glm::ivec2 readResolution(const Json& value, const Pointer& at) {
    if (!value.is_array() || value.size() != 2)
        fail(at, "expected an array of 2 integers (width, height)");
    glm::ivec2 resolution;
    for (int i = 0; i < 2; ++i) {
        const Json& size = value[i];
        bool isValid = size.is_number_integer() && size.get<std::int64_t>() >= 1 &&
                       size.get<std::int64_t>() <= kMaxResolution;
        if (!isValid)
            fail(at / i, "expected an integer in [1, " + std::to_string(kMaxResolution) + "]");
        resolution[i] = size.get<int>();
    }
    return resolution;
}

void checkKeys(const Json& object, const Pointer& at, std::initializer_list<const char*> allowed) {
    checkKeys<std::initializer_list<const char*>>(object, at, allowed);
}

// Which keys are allowed depends on "type", so it is read first; but when it is missing, a
// misspelt "typ" is the likely cause and is worth naming, so unknown keys (of any type) are
// reported first.
void requireType(const Json& object, const Pointer& at, const std::vector<const char*>& anyTypeKeys) {
    if (!object.contains("type")) {
        checkKeys(object, at, anyTypeKeys);
        fail(at / "type", "missing required key");
    }
}

glm::vec2 readVec2(const Json& value, const Pointer& at) {
    if (!value.is_array() || value.size() != 2) fail(at, "expected an array of 2 numbers");
    return {readNumber(value[0], at / 0), readNumber(value[1], at / 1)};
}

} // namespace ptview::sceneFile
