// Reads scene files (JSON, described in docs/scene-format.md) into the scene model.
//
// Scene files are written by hand, so every rejection names the file and the place in it as a
// JSON pointer, and anything unexpected (an unknown key, a wrong type, a number that is not
// finite) is an error rather than silently ignored: a typo such as "radus" would otherwise give a
// default radius and a puzzling image instead of a message.

#include "SceneLoader.h"

#include "GltfLoader.h"
#include "InputFile.h"
#include "MaterialSchema.h"
#include "MaterialTextures.h"
#include "TextureLoader.h"
#include "ObjLoader.h"
#include "SceneRanges.h"
#include "LightSchema.h"
#include "ShapeSchema.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <map>
#include <new>
#include <vector>

namespace ptview {
namespace {

// Ordered so that materials keep the order of the file, which the UI lists and Shape::material
// indexes.
using Json = nlohmann::ordered_json;
using Pointer = Json::json_pointer;

// Scene files are hand-written or saved text that names its meshes and maps; the largest in
// assets/ is a few KiB. A limit far above any real scene keeps /dev/zero or a mistyped multi-GiB
// file from being read into memory whole.
constexpr std::uintmax_t kMaxSceneFileBytes = 64 * kMiB;

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

// A problem at a place in the document. parseScene adds the file name, so the readers below
// need not carry it around.
class PlaceError : public std::runtime_error {
public:
    PlaceError(Pointer place, const std::string& reason)
        : std::runtime_error(reason), where(std::move(place)) {}
    Pointer where;
};

// Text that is not JSON at all; only a byte offset can say where.
class SyntaxError : public std::runtime_error {
public:
    SyntaxError(std::size_t byteOffset, const std::string& reason)
        : std::runtime_error(reason), offset(byteOffset) {}
    std::size_t offset; // of the offending byte; may be one past the end
};

// Keys and strings may hold escaped newlines ("a\nb"), which must not break the message in two.
SceneError oneLineError(const std::string& message) {
    std::string line;
    for (char c : message) {
        auto code = static_cast<unsigned char>(c);
        if (code < 0x20 || code == 0x7F) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04X", code);
            line += escaped;
        } else {
            line += c;
        }
    }
    return SceneError(line);
}

[[noreturn]] void fail(const Pointer& at, const std::string& reason) {
    throw PlaceError(at, reason);
}

std::string describe(const Json& value) {
    switch (value.type()) {
    case Json::value_t::object: return "an object";
    case Json::value_t::array: return "an array";
    case Json::value_t::string: return "a string";
    case Json::value_t::boolean: return "a boolean";
    case Json::value_t::null: return "null";
    default: return "a number";
    }
}

// nlohmann's messages carry an exception id and its own line/column (which counts a newline as
// column 0 of the next line); keep only the reason, without the echo of the last token, which
// for an unterminated string can be the rest of the file.
std::string shortSyntaxReason(std::string message) {
    auto dropThrough = [&message](const std::string& marker) {
        if (std::size_t at = message.find(marker); at != std::string::npos)
            message.erase(0, at + marker.size());
    };
    dropThrough("] ");
    if (message.rfind("parse error", 0) == 0)
        dropThrough(": ");
    if (message.rfind("syntax error while parsing", 0) == 0)
        dropThrough(" - ");
    const std::string lastRead = "; last read: '";
    if (std::size_t begin = message.find(lastRead); begin != std::string::npos) {
        std::size_t expected = message.find("'; expected ", begin + lastRead.size());
        std::size_t end = expected == std::string::npos ? message.size() : expected + 1;
        message.erase(begin, end - begin);
    }
    return message;
}

// How deeply arrays and objects may sit inside one another; a scene needs fewer than ten levels
// (the deepest: gltf / entry / materials / name / texture input / scale). Deeper documents are
// refused while they are read, before any recursive code sees them: ordered_json keeps an
// object's members in a vector of pair<const key, value>, which grows by copying its members (the
// pair's move copies the const key, may throw, so the vector does not use it), and that copy
// recurses once per level, as dump() and operator== do. A file of 100000 nested arrays followed
// by another key overflowed the stack.
constexpr std::size_t kMaxNesting = 64;

// Builds the document through nlohmann's SAX interface instead of Json::parse for three things
// Json::parse cannot do: reject duplicate keys (it keeps the last one silently, so a copied
// material that was not renamed would replace the original), name the value whose number
// overflows, such as 1e999 (it reports that without any position), and bound the nesting
// (kMaxNesting).
class DocumentBuilder final : public nlohmann::json_sax<Json> {
public:
    Json root;

    DocumentBuilder() = default;
    DocumentBuilder(const DocumentBuilder&) = delete;
    DocumentBuilder& operator=(const DocumentBuilder&) = delete;
    ~DocumentBuilder() override { dismantle(); }

    bool null() override { return addValue(nullptr); }
    bool boolean(bool value) override { return addValue(value); }
    bool number_integer(number_integer_t value) override { return addValue(value); }
    bool number_unsigned(number_unsigned_t value) override { return addValue(value); }
    bool number_float(number_float_t value, const string_t&) override { return addValue(value); }
    bool string(string_t& value) override { return addValue(std::move(value)); }
    bool binary(binary_t& value) override { return addValue(Json::binary(std::move(value))); }

    bool start_object(std::size_t) override { return openContainer(Json::object()); }
    bool end_object() override { return closeContainer(); }
    bool start_array(std::size_t) override { return openContainer(Json::array()); }
    bool end_array() override { return closeContainer(); }

    bool key(string_t& name) override {
        Frame& top = stack.back();
        if (top.container->contains(name))
            fail(placeWithin(stack.size() - 1) / name, "duplicate key");
        top.key = std::move(name);
        return true;
    }

    bool parse_error(std::size_t position, const std::string& lastToken,
                     const Json::exception& error) override {
        constexpr int kNumberOverflow = 406;
        if (error.id == kNumberOverflow)
            fail(placeWithin(stack.size()), "number " + lastToken + " is out of range");
        // position counts bytes read, so it is one past the offending byte.
        throw SyntaxError(position > 0 ? position - 1 : 0, shortSyntaxReason(error.what()));
    }

private:
    struct Frame {
        Json* container;
        std::string key; // objects: the key whose value is being read
    };
    // Pointers stay valid: only the innermost container grows, and none of its elements is open.
    std::vector<Frame> stack;

    // Frees the document innermost value first, so that no container still holds another when
    // it is destroyed. nlohmann's destructor moves nested containers onto a vector it allocates;
    // when the memory ran out while the document was built, that allocation fails inside a
    // destructor during the unwinding, which is std::terminate. The path down reuses `stack`,
    // whose capacity is the document's depth, so nothing here allocates.
    void dismantle() noexcept {
        stack.clear();
        if (root.is_structured()) stack.push_back({&root, {}});
        while (!stack.empty()) {
            Json& container = *stack.back().container;
            if (container.empty()) {
                stack.pop_back();
                continue;
            }
            Json& last = container.is_array() ? container.back() : container.get_ref<Json::object_t&>().back().second;
            if (last.is_structured() && !last.empty() && stack.size() < stack.capacity()) {
                stack.push_back({&last, {}});
                continue;
            }
            if (container.is_array()) container.get_ref<Json::array_t&>().pop_back();
            else container.get_ref<Json::object_t&>().pop_back();
        }
    }

    Json* place(Json&& value) {
        if (stack.empty()) {
            root = std::move(value);
            return &root;
        }
        Frame& top = stack.back();
        if (top.container->is_array()) {
            top.container->push_back(std::move(value));
            return &top.container->back();
        }
        Json& slot = (*top.container)[top.key];
        slot = std::move(value);
        return &slot;
    }
    bool addValue(Json&& value) {
        place(std::move(value));
        return true;
    }
    bool openContainer(Json&& empty) {
        // Named by the top-level member that holds it: the full pointer would be kMaxNesting
        // levels long, each a key of any length.
        if (stack.size() >= kMaxNesting)
            fail(placeWithin(1), "arrays and objects nested deeper than " + std::to_string(kMaxNesting) + " levels");
        stack.push_back({place(std::move(empty)), {}});
        return true;
    }
    bool closeContainer() {
        stack.pop_back();
        return true;
    }

    // The pointer through the outermost `depth` open containers. In an enclosing array the open
    // element is the last one; in the innermost container the value being read is not added yet.
    Pointer placeWithin(std::size_t depth) const {
        Pointer at;
        for (std::size_t i = 0; i < depth; ++i) {
            const Frame& frame = stack[i];
            if (frame.container->is_object()) {
                at /= frame.key;
            } else {
                bool isOpenElement = i + 1 < stack.size();
                at /= frame.container->size() - (isOpenElement ? 1 : 0);
            }
        }
        return at;
    }
};

// 1-based line and column (in UTF-8 characters, as editors count) of a byte offset.
std::pair<int, int> lineAndColumn(const std::string& text, std::size_t offset) {
    offset = std::min(offset, text.size());
    int line = 1;
    std::size_t lineStart = 0;
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++line;
            lineStart = i + 1;
        }
    }
    int column = 1;
    for (std::size_t i = lineStart; i < offset; ++i) {
        bool isContinuationByte = (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80;
        column += isContinuationByte ? 0 : 1;
    }
    return {line, column};
}

// Where a value still open at the end of text began (an object, an array or a string), with its
// kind; nullopt when none is open. A file cut short (an editor saving, a hot reload halfway
// through) only fails at its end, which says nothing about what is unclosed. When a brace is
// missing mid-file, the next closer closes the wrong value and the one left open is an outer
// one, often the whole document; in a file laid out by lines the mistake shows as a closer on a
// line of its own indented less than the line its (count-matched) opener is on, so that opener
// is named instead, as a guess.
struct UnclosedValue {
    const char* kind;
    std::size_t offset;
    std::optional<std::size_t> misplacedCloser; // set for the guess: the closer that gave it away
};

std::optional<UnclosedValue> unclosedValue(const std::string& text) {
    struct Open {
        UnclosedValue value;
        std::size_t lineIndent;
    };
    std::vector<Open> open;
    std::optional<UnclosedValue> guess;
    std::optional<std::size_t> stringStart;
    std::size_t indent = 0;
    bool onlySpaceSoFar = true; // on this line, before the current character
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (stringStart) {
            if (c == '\\') ++i; // the escaped character cannot end the string
            else if (c == '"') stringStart.reset();
            continue;
        }
        if (c == '\n') {
            indent = 0, onlySpaceSoFar = true;
            continue;
        }
        if (onlySpaceSoFar && (c == ' ' || c == '\t')) {
            ++indent;
            continue;
        }
        bool firstOnLine = onlySpaceSoFar;
        onlySpaceSoFar = false;
        if (c == '"') stringStart = i;
        else if (c == '{') open.push_back({{"object", i, std::nullopt}, indent});
        else if (c == '[') open.push_back({{"array", i, std::nullopt}, indent});
        else if ((c == '}' || c == ']') && !open.empty()) {
            if (firstOnLine && indent < open.back().lineIndent && !guess)
                guess = UnclosedValue{open.back().value.kind, open.back().value.offset, i};
            open.pop_back();
        }
    }
    if (stringStart) return UnclosedValue{"string", *stringStart, std::nullopt};
    if (open.empty()) return std::nullopt;
    return guess ? guess : open.back().value;
}

// --- Readers: each checks one value and names it on failure -------------------------------------

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

// --- Scene parts --------------------------------------------------------------------------------

CameraDesc readCamera(const Json& value, const Pointer& at) {
    requireObject(value, at);
    checkKeys(value, at, {"eye", "target", "up", "vfov_deg", "resolution", "aperture_radius", "focus_distance"});
    CameraDesc camera;
    camera.eye = readPosition(requireKey(value, at, "eye"), at / "eye");
    camera.target = readPosition(requireKey(value, at, "target"), at / "target");
    if (camera.target == camera.eye)
        fail(at / "target", "must differ from eye");
    if (const Json* up = optionalKey(value, "up")) {
        camera.up = readNonzeroVec3(*up, at / "up");
        if (areParallel(camera.up, camera.target - camera.eye))
            fail(at / "up", "must not be parallel to the view direction (target - eye)");
    } else if (areParallel(camera.up, camera.target - camera.eye)) {
        fail(at / "up", "missing, and the default [0, 1, 0] is parallel to the view direction");
    }
    camera.vfovDeg = readInRange(requireKey(value, at, "vfov_deg"), at / "vfov_deg", ranges::kVerticalFov);
    camera.resolution = readResolution(requireKey(value, at, "resolution"), at / "resolution");
    if (const Json* aperture = optionalKey(value, "aperture_radius"))
        camera.apertureRadius = readInRange(*aperture, at / "aperture_radius", ranges::kApertureRadius);
    const Json* focus = optionalKey(value, "focus_distance");
    camera.focusDistance = focus ? readInRange(*focus, at / "focus_distance", ranges::kFocusDistance)
                                 : defaultFocusDistance(camera);
    return camera;
}

// Either a constant "color" or a "map" (scaled by "intensity", turned by "rotation_deg"), never
// both: a colour beside a map would be silently unused. The map's path stays as written here;
// parseScene resolves it against the file's directory.
void readEnvironment(const Json& value, const Pointer& at, Scene& scene) {
    requireObject(value, at);
    checkKeys(value, at, {"color", "map", "intensity", "rotation_deg"});
    const Json* map = optionalKey(value, "map");
    if (!map) {
        for (const char* key : {"intensity", "rotation_deg"})
            if (optionalKey(value, key)) fail(at / key, "only allowed with \"map\"");
        if (!optionalKey(value, "color")) fail(at / "color", "missing required key (or give \"map\")");
        scene.environment = readVec3InRange(value.at("color"), at / "color", ranges::kRadiance);
        return;
    }
    if (optionalKey(value, "color")) fail(at / "color", "not allowed with \"map\" (the map gives the radiance)");
    std::string path = readString(*map, at / "map");
    if (path.empty()) fail(at / "map", "expected a file name, got an empty string");
    scene.environmentMap = std::filesystem::u8path(path);
    if (const Json* intensity = optionalKey(value, "intensity"))
        scene.environmentIntensity = readInRange(*intensity, at / "intensity", ranges::kEnvironmentIntensity);
    if (const Json* rotation = optionalKey(value, "rotation_deg"))
        scene.environmentRotationDeg = readInRange(*rotation, at / "rotation_deg", ranges::kEnvironmentRotation);
}

// A texture a material input names, decoded once the whole file is read (resolveTextures).
struct TextureRequest {
    std::size_t material;             // in Scene::materials
    TextureSlot Material::*slot;
    std::filesystem::path file;       // as written; resolved against the scene file's directory
    TextureColorSpace colorSpace;
    TextureWrap wrapU = TextureWrap::Repeat;
    TextureWrap wrapV = TextureWrap::Repeat;
    bool bilinear = true;
    Pointer at;                       // the "texture" key (or the input, when it is a bare path)
};

// The words of docs/scene-format.md for TextureWrap, in its order.
constexpr const char* kTextureWrapNames[] = {"repeat", "clamp", "mirror"};

TextureWrap readTextureWrap(const Json& value, const Pointer& at) {
    std::string name = readString(value, at);
    for (int i = 0; i < 3; ++i)
        if (name == kTextureWrapNames[i]) return static_cast<TextureWrap>(i);
    fail(at, "unknown wrap mode \"" + name + "\" (expected one of: repeat, clamp, mirror)");
}

glm::vec2 readVec2(const Json& value, const Pointer& at) {
    if (!value.is_array() || value.size() != 2) fail(at, "expected an array of 2 numbers");
    return {readNumber(value[0], at / 0), readNumber(value[1], at / 1)};
}

// A material input that may be textured: its plain value (readFactor), a texture's path (the
// factor is then 1), or {"texture": path, "factor": value, "scale": [su, sv], "offset": [ou, ov],
// "wrap": "repeat" | "clamp" | "mirror" | [u mode, v mode], "filter": "linear" | "nearest"}.
// Returns the factor; a texture becomes a request for the slot.
template <typename T, typename ReadFactor>
T readTexturedInput(const Json& value, const Pointer& at, ReadFactor readFactor, T one, TextureColorSpace colorSpace,
                    std::size_t materialIndex, TextureSlot Material::*slot, std::vector<TextureRequest>& requests) {
    if (!value.is_string() && !value.is_object()) return readFactor(value, at);
    TextureRequest request{materialIndex, slot, {}, colorSpace, TextureWrap::Repeat, TextureWrap::Repeat, true, at};
    T factor = one;
    if (value.is_string()) {
        request.file = std::filesystem::u8path(readString(value, at));
    } else {
        checkKeys(value, at, {"texture", "factor", "scale", "offset", "wrap", "filter"});
        request.at = at / "texture";
        request.file = std::filesystem::u8path(readString(requireKey(value, at, "texture"), at / "texture"));
        if (const Json* f = optionalKey(value, "factor")) factor = readFactor(*f, at / "factor");
        if (const Json* scale = optionalKey(value, "scale")) readVec2(*scale, at / "scale");
        if (const Json* offset = optionalKey(value, "offset")) readVec2(*offset, at / "offset");
        if (const Json* wrap = optionalKey(value, "wrap")) {
            if (wrap->is_array()) {
                if (wrap->size() != 2) fail(at / "wrap", "expected a wrap mode or an array of 2 (u, v)");
                request.wrapU = readTextureWrap((*wrap)[0], at / "wrap" / 0);
                request.wrapV = readTextureWrap((*wrap)[1], at / "wrap" / 1);
            } else {
                request.wrapU = request.wrapV = readTextureWrap(*wrap, at / "wrap");
            }
        }
        if (const Json* filter = optionalKey(value, "filter")) {
            std::string name = readString(*filter, at / "filter");
            if (name != "linear" && name != "nearest")
                fail(at / "filter", "unknown filter \"" + name + "\" (expected linear or nearest)");
            request.bilinear = name == "linear";
        }
    }
    if (request.file.empty()) fail(request.at, "expected a file name, got an empty string");
    requests.push_back(request);
    return factor;
}

// The scale and offset of a textured input's object form, applied to its slot once it is made.
void readTextureTransform(const Json& value, const Pointer& at, TextureSlot& slot) {
    if (!value.is_object()) return;
    if (const Json* scale = optionalKey(value, "scale")) slot.scale = readVec2(*scale, at / "scale");
    if (const Json* offset = optionalKey(value, "offset")) slot.offset = readVec2(*offset, at / "offset");
}

// A material of the "materials" section, or with `base` an override of a material a glTF file
// made (a "materials" entry of a "gltf" entry): then every key is optional, a key left out keeps
// the file's value, and "type" defaults to the file's. A type change starts from the new type's
// defaults, as the Materials panel's does, and keeps the file's value of each of its keys left
// out. A textured input in an override may be an object without "texture", which keeps the
// file's texture (which may be embedded in a .glb, where no path can name it) and sets its
// factor, scale or offset; a plain value means no texture.
Material readMaterial(const std::string& name, const Json& value, const Pointer& at, std::size_t index,
                      std::vector<TextureRequest>& textures, const Material* base = nullptr) {
    requireObject(value, at);
    Material material;
    material.name = name;
    const MaterialSchema* schema = base ? &materialSchema(base->type) : nullptr;
    if (!base || value.contains("type")) {
        requireType(value, at, anyMaterialKeys());
        std::string type = readString(value.at("type"), at / "type");
        schema = findMaterialSchema(type);
        if (!schema) {
            std::string typeList;
            for (const MaterialSchema& candidate : kMaterialSchemas)
                typeList += (typeList.empty() ? "" : ", ") + std::string(candidate.name);
            fail(at / "type", "unknown material type \"" + type + "\" (expected one of: " + typeList + ")");
        }
    }
    checkKeys(value, at, materialKeys(*schema));
    if (base) {
        if (schema->type == base->type) material = *base;
        else
            for (const char* key : materialKeys(*schema))
                if (!value.contains(key)) copyMaterialInput(*schema, key, *base, material);
        material.importedFrom = base->importedFrom;
    }
    material.type = schema->type;
    const bool principled = schema->type == MaterialType::Principled;

    auto readColor = [](const Json& v, const Pointer& p) { return readVec3InRange(v, p, ranges::kColor); };
    auto readRadiance = [](const Json& v, const Pointer& p) { return readVec3InRange(v, p, ranges::kRadiance); };
    auto readIn = [](const SceneRange& range) {
        return [&range](const Json& v, const Pointer& p) { return readInRange(v, p, range); };
    };
    // Any input may be textured but an emitter's radiance (its light table entry needs one value).
    // `fileFactor`: the base's value of the input, which an override's object without "texture" keeps.
    auto textured = [&](const char* key, auto read, auto one, TextureSlot Material::*slot, auto fileFactor) {
        const Json& input = value.at(key);
        const Pointer inputAt = at / key;
        if (base && input.is_object() && !input.contains("texture")) {
            checkKeys(input, inputAt, {"texture", "factor", "scale", "offset"});
            material.*slot = (*base).*slot;
            readTextureTransform(input, inputAt, material.*slot);
            const Json* factor = optionalKey(input, "factor");
            return factor ? read(*factor, inputAt / "factor") : fileFactor;
        }
        // A texture replaces the slot whole; a plain value leaves none (an override's slot may have one).
        if (input.is_string() || input.is_object()) material.*slot = TextureSlot{};
        else (material.*slot).texture = -1;
        auto factor = readTexturedInput(input, inputAt, read, one, colorSpaceOf(slot), index, slot, textures);
        readTextureTransform(input, inputAt, material.*slot);
        return factor;
    };
    const Material fileValues = base ? *base : Material{};

    const Json* radiance = schema->radianceRequired && !base ? &requireKey(value, at, schema->radianceKey)
                                                             : optionalKey(value, schema->radianceKey);
    if (radiance) {
        material.radiance = schema->radianceRequired
                                ? readRadiance(*radiance, at / schema->radianceKey)
                                : textured(schema->radianceKey, readRadiance, glm::vec3(1.0f),
                                           &Material::emissionTexture, fileValues.radiance);
    }
    if (schema->colorKey) {
        const Json* color = schema->colorDefault || base ? optionalKey(value, schema->colorKey)
                                                         : &requireKey(value, at, schema->colorKey);
        if (color)
            material.color = textured(schema->colorKey, readColor, glm::vec3(1.0f), &Material::baseColorTexture,
                                      fileValues.color);
        else if (!base)
            material.color = *schema->colorDefault;
    }
    if (schema->hasIor) {
        if (const Json* ior = optionalKey(value, "ior")) material.ior = readInRange(*ior, at / "ior", ranges::kIor);
    }
    if (schema->hasRoughness) {
        if (optionalKey(value, "roughness"))
            material.roughness = textured("roughness", readIn(ranges::kRoughness), 1.0f, &Material::roughnessTexture,
                                          fileValues.roughness);
    }
    if (principled) {
        // glTF's defaults: fully metallic and rough when the file says nothing would surprise in
        // a hand-written scene, so ours are a smooth-ish dielectric: metallic 0, roughness 0.5.
        if (!optionalKey(value, "roughness") && !base) material.roughness = 0.5f;
        if (optionalKey(value, "metallic"))
            material.metallic = textured("metallic", readIn(ranges::kMetallic), 1.0f, &Material::metallicTexture,
                                         fileValues.metallic);
        if (const Json* t = optionalKey(value, "transmission"))
            material.transmission = readInRange(*t, at / "transmission", ranges::kTransmission);
        if (const Json* a = optionalKey(value, "alpha")) material.alpha = readInRange(*a, at / "alpha", ranges::kAlpha);
        if (const Json* c = optionalKey(value, "alpha_cutoff"))
            material.alphaCutoff = readInRange(*c, at / "alpha_cutoff", ranges::kAlphaCutoff);
        // A tangent-space normal map: its factor is glTF's normalTexture.scale. Without a texture
        // the key would say nothing, so a bare number is refused rather than ignored; in an
        // override it says that the file's normal map is removed (and keeps the scale).
        if (const Json* normalMap = optionalKey(value, "normal_map")) {
            if (!normalMap->is_string() && !normalMap->is_object() && !base)
                fail(at / "normal_map", "expected a texture: a file name or {\"texture\": file, \"factor\": scale}");
            material.normalScale = textured("normal_map", readIn(ranges::kNormalScale), 1.0f, &Material::normalTexture,
                                            fileValues.normalScale);
        }
        if (const Json* mode = optionalKey(value, "alpha_mode")) {
            std::string name = readString(*mode, at / "alpha_mode");
            if (name == "opaque") material.alphaMode = AlphaMode::Opaque;
            else if (name == "mask") material.alphaMode = AlphaMode::Mask;
            else if (name == "blend") material.alphaMode = AlphaMode::Blend;
            else fail(at / "alpha_mode", "unknown alpha mode \"" + name + "\" (expected one of: opaque, mask, blend)");
        }
        if (const Json* strength = optionalKey(value, "emission_strength")) {
            float s = readInRange(*strength, at / "emission_strength", ranges::kRadiance);
            material.radiance *= s;
            if (!ranges::kRadiance.contains(material.radiance.r) || !ranges::kRadiance.contains(material.radiance.g) ||
                !ranges::kRadiance.contains(material.radiance.b))
                fail(at / "emission_strength", "emission x strength is out of range (" + ranges::kRadiance.text() + ")");
        }
    }
    return material;
}

int findMaterial(const std::vector<Material>& materials, const std::string& name) {
    auto it = std::find_if(materials.begin(), materials.end(),
                           [&](const Material& m) { return m.name == name; });
    return it == materials.end() ? -1 : static_cast<int>(std::distance(materials.begin(), it));
}

// "rotation": {"axis": [x, y, z], "degrees": d}, as boxes and transforms write it.
void readRotation(const Json& value, const Pointer& at, glm::vec3& axis, float& degrees) {
    requireObject(value, at);
    checkKeys(value, at, {"axis", "degrees"});
    axis = readNonzeroVec3(requireKey(value, at, "axis"), at / "axis");
    degrees = readNumber(requireKey(value, at, "degrees"), at / "degrees");
}

Transform readTransform(const Json& value, const Pointer& at) {
    requireObject(value, at);
    checkKeys(value, at, {"translate", "rotation", "scale"});
    Transform transform;
    if (const Json* translate = optionalKey(value, "translate"))
        transform.translate = readPosition(*translate, at / "translate");
    if (const Json* rotation = optionalKey(value, "rotation"))
        readRotation(*rotation, at / "rotation", transform.rotationAxis, transform.rotationDeg);
    if (const Json* scale = optionalKey(value, "scale")) {
        // One number scales uniformly; zero would flatten the object to nothing.
        transform.scale = scale->is_number() ? glm::vec3(readNumber(*scale, at / "scale"))
                                             : readVec3(*scale, at / "scale", [](float c) { return c != 0.0f; },
                                                        "a nonzero number");
        if (transform.scale.x == 0.0f) fail(at / "scale", "expected a nonzero number");
    }
    return transform;
}

// Spheres, disks and rotated boxes stay what they are only under a uniform scale, and boxes only
// under a positive one, so anything else is an error, not a silent change (bakeTransform's terms).
void checkTransformable(const Shape& shape, const Transform& transform, const Pointer& at) {
    switch (shape.type) {
    case ShapeType::Sphere:
        if (!isUniform(transform.scale)) fail(at / "scale", "a sphere takes only a uniform scale");
        break;
    case ShapeType::Disk:
        if (!isUniform(transform.scale)) fail(at / "scale", "a disk takes only a uniform scale");
        break;
    case ShapeType::Box:
        if (!isUniform(transform.scale) && shape.rotationDeg != 0.0f)
            fail(at / "scale", "a rotated box takes only a uniform scale (a sheared box is not a box)");
        if (transform.scale.x < 0.0f || transform.scale.y < 0.0f || transform.scale.z < 0.0f)
            fail(at / "scale", "a box takes only a positive scale");
        break;
    case ShapeType::Quad:
    case ShapeType::Mesh:
        break;
    }
}

// The bounds hold for what is stored, after the transform: a radius of 1e8 scaled by 100 is as far
// out of range as one of 1e10 written so. The message names the transformed value.
void checkTransformedShape(const Shape& shape, const Pointer& at) {
    auto refuse = [&](const std::string& what, double value) {
        fail(at / "transform", "gives a " + what + " of " + boundText(static_cast<float>(std::min(value, 3.4e38))) +
                                   ", above " + boundText(kMaxExtent) + " (metres)");
    };
    for (int i = 0; i < 3; ++i)
        if (!(std::abs(shape.center[i]) <= kMaxExtent)) refuse("centre coordinate", std::abs(shape.center[i]));
    switch (shape.type) {
    case ShapeType::Sphere:
    case ShapeType::Disk:
        if (!(shape.radius <= kMaxExtent)) refuse("radius", shape.radius);
        break;
    case ShapeType::Quad:
        if (!(glm::length(glm::dvec3(shape.u)) <= kMaxExtent)) refuse("length of u", glm::length(glm::dvec3(shape.u)));
        if (!(glm::length(glm::dvec3(shape.v)) <= kMaxExtent)) refuse("length of v", glm::length(glm::dvec3(shape.v)));
        break;
    case ShapeType::Box:
        for (int i = 0; i < 3; ++i)
            if (!(shape.halfSize[i] <= kMaxExtent)) refuse("half size", shape.halfSize[i]);
        break;
    case ShapeType::Mesh:
        break;
    }
}

// How a mesh shape named its materials; resolved once the mesh file is read.
struct MeshMaterialRequest {
    std::size_t shape;
    Pointer at;
    std::optional<std::string> material;             // "material": every slot not named below
    std::vector<std::pair<std::string, std::string>> bySlot; // "materials": OBJ name -> scene material
};

Shape readShape(const Json& value, const Pointer& at, std::size_t index,
                const std::vector<Material>& materials, const std::map<std::string, int>& meshes,
                std::vector<MeshMaterialRequest>& meshRequests) {
    requireObject(value, at);
    Shape shape;
    requireType(value, at, anyShapeKeys());
    std::string type = readString(value.at("type"), at / "type");
    const ShapeSchema* schema = findShapeSchema(type);
    if (!schema) fail(at / "type", "unknown shape type \"" + type + "\" (expected " + schemaNameList(kShapeSchemas) + ")");
    shape.type = schema->type;
    checkKeys(value, at, shapeKeys(*schema));

    const Json* name = optionalKey(value, "name");
    shape.name = name ? readString(*name, at / "name") : type + " " + std::to_string(index);
    const Json* transform = optionalKey(value, "transform");
    if (transform) shape.transform = readTransform(*transform, at / "transform");

    if (shape.type == ShapeType::Mesh) {
        std::string meshName = readString(requireKey(value, at, "mesh"), at / "mesh");
        auto mesh = meshes.find(meshName);
        if (mesh == meshes.end()) fail(at / "mesh", "unknown mesh \"" + meshName + "\" (declare it under \"meshes\")");
        shape.mesh = mesh->second;
        MeshMaterialRequest request{index, at, std::nullopt, {}};
        if (const Json* material = optionalKey(value, "material")) {
            request.material = readString(*material, at / "material");
            if (findMaterial(materials, *request.material) < 0)
                fail(at / "material", "unknown material \"" + *request.material + "\"");
        }
        if (const Json* bySlot = optionalKey(value, "materials")) {
            requireObject(*bySlot, at / "materials");
            for (auto it = bySlot->begin(); it != bySlot->end(); ++it) {
                std::string target = readString(it.value(), at / "materials" / it.key());
                if (findMaterial(materials, target) < 0)
                    fail(at / "materials" / it.key(), "unknown material \"" + target + "\"");
                request.bySlot.emplace_back(it.key(), target);
            }
        }
        meshRequests.push_back(std::move(request));
        return shape;
    }

    std::string materialName = readString(requireKey(value, at, "material"), at / "material");
    shape.material = findMaterial(materials, materialName);
    if (shape.material < 0)
        fail(at / "material", "unknown material \"" + materialName + "\"");
    shape.center = readPosition(requireKey(value, at, "center"), at / "center");

    switch (shape.type) {
    case ShapeType::Sphere:
        shape.radius = readLength(requireKey(value, at, "radius"), at / "radius");
        break;
    case ShapeType::Quad:
        shape.u = readEdge(requireKey(value, at, "u"), at / "u");
        shape.v = readEdge(requireKey(value, at, "v"), at / "v");
        // A degenerate quad has no area and no normal.
        if (areParallel(shape.u, shape.v))
            fail(at / "v", "must not be parallel to u");
        break;
    case ShapeType::Box:
        shape.halfSize = readVec3(requireKey(value, at, "half_size"), at / "half_size",
                                  [](float c) { return c > 0.0f && c <= kMaxExtent; },
                                  ("a positive number at most " + boundText(kMaxExtent) + " (metres)").c_str());
        if (const Json* rotation = optionalKey(value, "rotation"))
            readRotation(*rotation, at / "rotation", shape.rotationAxis, shape.rotationDeg);
        break;
    case ShapeType::Disk:
        shape.normal = readDirection(requireKey(value, at, "normal"), at / "normal");
        shape.radius = readLength(requireKey(value, at, "radius"), at / "radius");
        break;
    case ShapeType::Mesh:
        break;
    }
    if (transform) {
        checkTransformable(shape, shape.transform, at / "transform");
        bakeTransform(shape, shape.transform);
        shape.transform = Transform{};
        checkTransformedShape(shape, at);
    }
    return shape;
}

// A value the file left out, for messages that mention it.
std::string defaultText(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g, the default", static_cast<double>(value));
    return text;
}

Light readLight(const Json& value, const Pointer& at, std::size_t index) {
    requireObject(value, at);
    Light light;
    requireType(value, at, anyLightKeys());
    std::string type = readString(value.at("type"), at / "type");
    const LightSchema* schema = findLightSchema(type);
    if (!schema) fail(at / "type", "unknown light type \"" + type + "\" (expected " + schemaNameList(kLightSchemas) + ")");
    light.type = schema->type;
    checkKeys(value, at, lightKeys(*schema));

    const Json* name = optionalKey(value, "name");
    light.name = name ? readString(*name, at / "name") : type + " " + std::to_string(index);
    if (light.type != LightType::Directional)
        light.position = readPosition(requireKey(value, at, "position"), at / "position");
    // A directional light's "intensity" is the irradiance it gives a surface facing it (Scene.h).
    light.intensity = readVec3InRange(requireKey(value, at, "intensity"), at / "intensity", ranges::kIntensity);
    if (light.type != LightType::Point)
        light.direction = readDirection(requireKey(value, at, "direction"), at / "direction");
    if (light.type == LightType::Spot) {
        const Json* inner = optionalKey(value, "inner_deg");
        const Json* outer = optionalKey(value, "outer_deg");
        if (inner) light.innerAngleDeg = readInRange(*inner, at / "inner_deg", ranges::kSpotConeAngle);
        if (outer) light.outerAngleDeg = readInRange(*outer, at / "outer_deg", ranges::kSpotConeAngle);
        bool ordered = ranges::coneAnglesOrdered(light.innerAngleDeg, light.outerAngleDeg);
        // Blame an angle the file gives, the inner one when it gives both.
        if (!ordered && inner)
            fail(at / "inner_deg", "must not exceed outer_deg (" +
                                       (outer ? outer->dump() : defaultText(light.outerAngleDeg)) + ")");
        if (!ordered)
            fail(at / "outer_deg", "must not be less than inner_deg (" + defaultText(light.innerAngleDeg) + ")");
    }
    return light;
}

// The scene as read from JSON, before its mesh files are: what parseScene still has to resolve.
struct SceneDraft {
    Scene scene;
    std::vector<Pointer> meshPlaces; // where each of scene.meshes was declared
    std::vector<MeshMaterialRequest> meshRequests;
    std::vector<TextureRequest> textureRequests;
    std::vector<Pointer> importPlaces; // where each of scene.imports was declared
    std::vector<const Json*> importOverrides; // each entry's "materials", or null; applied once the file is read
    std::vector<const Json*> importLightOverrides; // each entry's "lights", or null
};

// "gltf": [{"file": "helmet.glb", "transform": {...}, "materials": {...}}]: glTF files placed in
// the scene, read once the rest is, and their materials' overrides (resolveImports).
void readImports(const Json& value, const Pointer& at, SceneDraft& draft) {
    if (!value.is_array()) fail(at, "expected an array, got " + describe(value));
    for (std::size_t i = 0; i < value.size(); ++i) {
        const Pointer entryAt = at / i;
        requireObject(value[i], entryAt);
        checkKeys(value[i], entryAt, {"file", "transform", "materials", "lights"});
        SceneImport entry;
        std::string file = readString(requireKey(value[i], entryAt, "file"), entryAt / "file");
        if (!isGltfFile(std::filesystem::u8path(file)))
            fail(entryAt / "file", "expected a .gltf or .glb file, got \"" + file + "\"");
        entry.file = std::filesystem::u8path(file);
        if (const Json* transform = optionalKey(value[i], "transform"))
            entry.transform = readTransform(*transform, entryAt / "transform");
        const Json* overrides = optionalKey(value[i], "materials");
        if (overrides) requireObject(*overrides, entryAt / "materials");
        draft.scene.imports.push_back(entry);
        draft.importPlaces.push_back(entryAt / "file");
        draft.importOverrides.push_back(overrides);
        const Json* lightOverrides = optionalKey(value[i], "lights");
        if (lightOverrides) requireObject(*lightOverrides, entryAt / "lights");
        draft.importLightOverrides.push_back(lightOverrides);
    }
}

SceneDraft readScene(const Json& root) {
    const Pointer top;
    if (!root.is_object())
        fail(top, "expected an object at the top level, got " + describe(root));
    checkKeys(root, top, {"camera", "environment", "materials", "meshes", "shapes", "lights", "gltf"});

    SceneDraft draft;
    Scene& scene = draft.scene;
    scene.camera = readCamera(requireKey(root, top, "camera"), top / "camera");
    if (const Json* environment = optionalKey(root, "environment"))
        readEnvironment(*environment, top / "environment", scene);

    const Pointer materialsAt = top / "materials";
    const Json& materials = requireObject(requireKey(root, top, "materials"), materialsAt);
    for (auto it = materials.begin(); it != materials.end(); ++it)
        scene.materials.push_back(
            readMaterial(it.key(), it.value(), materialsAt / it.key(), scene.materials.size(), draft.textureRequests));

    std::map<std::string, int> meshIndex;
    if (const Json* meshes = optionalKey(root, "meshes")) {
        const Pointer meshesAt = top / "meshes";
        requireObject(*meshes, meshesAt);
        for (auto it = meshes->begin(); it != meshes->end(); ++it) {
            Pointer at = meshesAt / it.key();
            requireObject(it.value(), at);
            checkKeys(it.value(), at, {"file"});
            std::string file = readString(requireKey(it.value(), at, "file"), at / "file");
            if (file.empty()) fail(at / "file", "expected a file name, got an empty string");
            meshIndex[it.key()] = static_cast<int>(scene.meshes.size());
            scene.meshes.push_back(SceneMesh{it.key(), std::filesystem::u8path(file), nullptr});
            draft.meshPlaces.push_back(at / "file");
        }
    }

    const Pointer shapesAt = top / "shapes";
    const Json& shapes = requireKey(root, top, "shapes");
    if (!shapes.is_array())
        fail(shapesAt, "expected an array, got " + describe(shapes));
    for (std::size_t i = 0; i < shapes.size(); ++i)
        scene.shapes.push_back(readShape(shapes[i], shapesAt / i, i, scene.materials, meshIndex, draft.meshRequests));

    if (const Json* lights = optionalKey(root, "lights")) {
        const Pointer lightsAt = top / "lights";
        if (!lights->is_array())
            fail(lightsAt, "expected an array, got " + describe(*lights));
        for (std::size_t i = 0; i < lights->size(); ++i)
            scene.lights.push_back(readLight((*lights)[i], lightsAt / i, i));
    }
    if (const Json* gltf = optionalKey(root, "gltf")) readImports(*gltf, top / "gltf", draft);
    return draft;
}

// A texture slot for an MTL map: one scene texture per image, colour space and wrap, however
// many materials use it; the map's -s/-o in the slot. A map without an image (missing or not
// decoded, already warned about) leaves the slot empty: the factor alone.
TextureSlot textureSlotFromMap(const MeshTextureMap& map, TextureColorSpace colorSpace, Scene& scene) {
    TextureSlot slot;
    if (!map.image) return slot;
    const TextureWrap wrap = map.clamp ? TextureWrap::ClampToEdge : TextureWrap::Repeat;
    slot.scale = map.scale;
    slot.offset = map.offset;
    for (std::size_t i = 0; i < scene.textures.size(); ++i) {
        const SceneTexture& texture = scene.textures[i];
        if (texture.image == map.image && texture.colorSpace == colorSpace && texture.wrapU == wrap && texture.wrapV == wrap) {
            slot.texture = static_cast<int>(i);
            return slot;
        }
    }
    SceneTexture texture;
    texture.source = map.file.string();
    texture.file = map.file;
    texture.colorSpace = colorSpace;
    texture.wrapU = texture.wrapV = wrap;
    texture.image = map.image;
    slot.texture = static_cast<int>(scene.textures.size());
    scene.textures.push_back(std::move(texture));
    return slot;
}

// An MTL entry with texture maps as a principled material (docs/scene-format.md, "MTL
// materials"): Kd x map_Kd the base colour, Ke x map_Ke the emission, Pr x map_Pr the roughness
// (without Pr, 1 with a map, else from Ns as for plastic), Pm x map_Pm the metallic (without Pm,
// 1 with a map, else 0), norm or map_Bump
// the normal map (-bm its scale), d the alpha (blended below 1), illum 4, 6 or 7 full transmission.
Material principledFromMeshFile(const MeshMaterial& source, float roughnessFromNs, Scene& scene) {
    Material material;
    material.type = MaterialType::Principled;
    material.color = glm::clamp(source.diffuse, 0.0f, 1.0f);
    // A map multiplies its factor; without Pr or Pm a map that loaded has the factor 1, so that it
    // gives the value (a metallic factor of 0 would make map_Pm do nothing).
    material.roughness = std::clamp(source.roughness.value_or(source.roughnessMap.image ? 1.0f : roughnessFromNs), 0.0f, 1.0f);
    material.metallic = std::clamp(source.metallic.value_or(source.metallicMap.image ? 1.0f : 0.0f), 0.0f, 1.0f);
    // tinyobjloader's Ni is 1 when the entry leaves it out, and exporters write 1 for "not set":
    // an index of 1 would give a dielectric no reflection at all.
    material.ior = source.ior > 1.0f ? std::min(source.ior, 4.0f) : 1.5f;
    material.alpha = std::clamp(source.dissolve, 0.0f, 1.0f);
    material.alphaMode = material.alpha < 1.0f ? AlphaMode::Blend : AlphaMode::Opaque;
    if (source.illum == 4 || source.illum == 6 || source.illum == 7) material.transmission = 1.0f;
    material.normalScale = source.normalMap.bumpMultiplier;
    material.baseColorTexture = textureSlotFromMap(source.diffuseMap, colorSpaceOf(&Material::baseColorTexture), scene);
    material.emissionTexture = textureSlotFromMap(source.emissionMap, colorSpaceOf(&Material::emissionTexture), scene);
    material.roughnessTexture = textureSlotFromMap(source.roughnessMap, colorSpaceOf(&Material::roughnessTexture), scene);
    material.metallicTexture = textureSlotFromMap(source.metallicMap, colorSpaceOf(&Material::metallicTexture), scene);
    material.normalTexture = textureSlotFromMap(source.normalMap, colorSpaceOf(&Material::normalTexture), scene);
    return material;
}

// A scene material made from a mesh file's own (MTL) material, for slots the scene file does
// not map: the closest of our models, named "MESH/NAME" so it shows as the mesh's. An entry
// with texture maps is principled; its textures are added to the scene.
Material materialFromMeshFile(const std::string& meshName, const MeshMaterial& source, Scene& scene) {
    // Phong exponent to roughness: alpha = sqrt(2 / (Ns + 2)) and alpha = roughness^2.
    const float roughnessFromNs = std::sqrt(std::sqrt(2.0f / (std::max(source.shininess, 0.0f) + 2.0f)));
    if (source.hasTextureMaps()) {
        Material material = principledFromMeshFile(source, roughnessFromNs, scene);
        material.name = meshName + "/" + source.name;
        material.radiance = glm::clamp(source.emission, 0.0f, kMaxRadiance);
        return material;
    }
    Material material;
    material.name = meshName + "/" + source.name;
    glm::vec3 diffuse = glm::clamp(source.diffuse, 0.0f, 1.0f);
    glm::vec3 specular = glm::clamp(source.specular, 0.0f, 1.0f);
    float specularLevel = std::max(specular.r, std::max(specular.g, specular.b));
    float diffuseLevel = std::max(diffuse.r, std::max(diffuse.g, diffuse.b));
    const float roughness = roughnessFromNs;
    if (source.dissolve < 1.0f || source.illum == 4 || source.illum == 6 || source.illum == 7) {
        material.type = MaterialType::Glass;
        material.color = glm::vec3(1.0f);
        material.ior = std::clamp(source.ior, 1.0f, 4.0f);
    } else if (specularLevel > 0.0f && diffuseLevel <= 0.01f) {
        material.type = MaterialType::Metal;
        material.color = specular;
        material.roughness = roughness;
    } else if (specularLevel > 0.0f) {
        material.type = MaterialType::Plastic;
        material.color = diffuse;
        material.ior = 1.5f;
        material.roughness = roughness;
    } else {
        material.type = MaterialType::Diffuse;
        material.color = diffuse;
    }
    // Clamped to the bound a scene file's radiance has (SceneRanges.h), as the colours above are to
    // [0, 1]: "Ke 1e20" in an MTL is no more renderable than in a scene file.
    material.radiance = glm::clamp(source.emission, 0.0f, kMaxRadiance);
    return material;
}

// Reads each mesh file once and gives every slot of every mesh shape a scene material: the
// shape's "materials" entry for it, else its "material", else the scene material of the same
// name, else one made from the mesh file's own definition.
void resolveMeshes(SceneDraft& draft, const std::filesystem::path& sceneFile, const ReadScope& scope) {
    Scene& scene = draft.scene;
    TextureBudget textureBudget(decodedTextureBytes(scene)); // every mesh's MTL maps together
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        SceneMesh& mesh = scene.meshes[m];
        if (mesh.file.is_relative()) mesh.file = sceneFile.parent_path() / mesh.file;
        if (std::optional<std::string> refusal = scope.refusal(mesh.file)) fail(draft.meshPlaces[m], *refusal);
        MeshLoadReport report;
        try {
            mesh.data = std::make_shared<const TriangleMesh>(loadObjMesh(mesh.file, &report, scope, &textureBudget));
        } catch (const MeshError& error) {
            // The mesh's own error names its file and line; say which scene entry wanted it.
            fail(draft.meshPlaces[m], error.what());
        }
        scene.warnings.insert(scene.warnings.end(), report.warnings.begin(), report.warnings.end());
    }
    for (const MeshMaterialRequest& request : draft.meshRequests) {
        Shape& shape = scene.shapes[request.shape];
        const SceneMesh& mesh = scene.meshes[static_cast<std::size_t>(shape.mesh)];
        const TriangleMesh& data = *mesh.data;
        std::vector<bool> slotUsed(data.materialSlots.size(), false);
        for (const MeshTriangle& triangle : data.triangles) slotUsed[static_cast<std::size_t>(triangle.materialSlot)] = true;
        for (const auto& [slotName, target] : request.bySlot) {
            if (std::find(data.materialSlots.begin(), data.materialSlots.end(), slotName) == data.materialSlots.end())
                fail(request.at / "materials" / slotName,
                     "the mesh \"" + mesh.name + "\" has no material slot \"" + slotName + "\" (no usemtl of that name)");
        }
        shape.slotMaterials.assign(data.materialSlots.size(), -1);
        for (std::size_t slot = 0; slot < data.materialSlots.size(); ++slot) {
            const std::string& slotName = data.materialSlots[slot];
            int material = -1;
            for (const auto& [name, target] : request.bySlot)
                if (name == slotName) material = findMaterial(scene.materials, target);
            if (material < 0 && request.material) material = findMaterial(scene.materials, *request.material);
            if (material < 0 && !slotName.empty()) material = findMaterial(scene.materials, slotName);
            if (material < 0 && !slotName.empty()) {
                auto own = std::find_if(data.fileMaterials.begin(), data.fileMaterials.end(),
                                        [&](const MeshMaterial& candidate) { return candidate.name == slotName; });
                if (own != data.fileMaterials.end()) {
                    const std::string madeName = mesh.name + "/" + own->name;
                    material = findMaterial(scene.materials, madeName);
                    if (material < 0) {
                        material = static_cast<int>(scene.materials.size());
                        scene.materials.push_back(materialFromMeshFile(mesh.name, *own, scene));
                    }
                }
            }
            if (material < 0 && slotUsed[slot])
                fail(request.at / "material",
                     slotName.empty() ? "missing: the mesh \"" + mesh.name + "\" has faces without a material (usemtl)"
                                      : "missing: nothing gives a material for the mesh's \"" + slotName +
                                            "\" faces (add \"materials\": {\"" + slotName + "\": ...})");
            shape.slotMaterials[slot] = std::max(material, 0);
        }
    }
}

// Decodes every texture the materials name, each file once (TextureLoader.h), relative to the
// scene file; textures of the same file and sampler are one Scene::textures entry. Every file's
// size is charged to the scene's texture budget from its header before any is decoded.
void resolveTextures(const std::vector<TextureRequest>& requests, const std::filesystem::path& sceneFile,
                     const ReadScope& scope, Scene& scene) {
    TextureImageCache cache(decodedTextureBytes(scene));
    auto fileOf = [&](const TextureRequest& request) {
        return request.file.is_relative() ? sceneFile.parent_path() / request.file : request.file;
    };
    for (const TextureRequest& request : requests) {
        std::filesystem::path file = fileOf(request);
        if (std::optional<std::string> refusal = scope.refusal(file)) fail(request.at, *refusal);
        try {
            cache.reserve(file);
        } catch (const TextureError& error) {
            fail(request.at, error.what());
        }
    }
    for (const TextureRequest& request : requests) {
        std::filesystem::path file = fileOf(request);
        int index = -1;
        for (std::size_t t = 0; t < scene.textures.size() && index < 0; ++t) {
            const SceneTexture& known = scene.textures[t];
            if (known.file == file && known.colorSpace == request.colorSpace && known.wrapU == request.wrapU &&
                known.wrapV == request.wrapV && known.bilinear == request.bilinear)
                index = static_cast<int>(t);
        }
        if (index < 0) {
            SceneTexture texture;
            texture.source = file.string();
            texture.file = file;
            texture.colorSpace = request.colorSpace;
            texture.wrapU = request.wrapU;
            texture.wrapV = request.wrapV;
            texture.bilinear = request.bilinear;
            try {
                texture.image = cache.load(file);
            } catch (const TextureError& error) {
                fail(request.at, error.what());
            }
            index = static_cast<int>(scene.textures.size());
            scene.textures.push_back(std::move(texture));
        }
        (scene.materials[request.material].*request.slot).texture = index;
    }
}

// The error for an override whose key names none of the parts (materials, lights) a glTF file made,
// listing a few of their names.
template <typename Part>
[[noreturn]] void failNotInFile(const Pointer& at, const char* kind, const SceneImport& entry, const std::vector<Part>& parts) {
    std::string names;
    for (std::size_t i = 0; i < parts.size() && i < 4; ++i) names += (names.empty() ? "" : ", ") + ("\"" + parts[i].name + "\"");
    if (parts.size() > 4) names += ", ...";
    fail(at, std::string("no ") + kind + " of " + entry.file.filename().string() + " has this name (" +
                 (names.empty() ? "it has none" : "it has " + names) + ")");
}

// An entry's "materials": each key names a material the file made (in scene.materials from
// `first` on), its value an override of it (readMaterial with a base). Texture files the overrides
// name become requests.
void applyMaterialOverrides(const Json& overrides, const Pointer& at, const SceneImport& entry, std::size_t first,
                            Scene& scene, std::vector<TextureRequest>& textures) {
    for (auto it = overrides.begin(); it != overrides.end(); ++it) {
        int found = findMaterial(scene.materials, it.key());
        if (found < static_cast<int>(first)) failNotInFile(at / it.key(), "material", entry, entry.fileMaterials); // -1: none at all
        Material& material = scene.materials[static_cast<std::size_t>(found)];
        const Material file = material;
        material = readMaterial(file.name, it.value(), at / it.key(), static_cast<std::size_t>(found), textures, &file);
    }
}

// An entry's "lights": each key names a light the file made (in scene.lights from `first` on), its
// value the whole light in the syntax of "lights" but for its name, which the key gives.
void applyLightOverrides(const Json& overrides, const Pointer& at, const SceneImport& entry, int importIndex,
                         std::size_t first, Scene& scene) {
    for (auto it = overrides.begin(); it != overrides.end(); ++it) {
        auto found = std::find_if(scene.lights.begin() + static_cast<std::ptrdiff_t>(first), scene.lights.end(),
                                  [&](const Light& light) { return light.name == it.key(); });
        if (found == scene.lights.end()) failNotInFile(at / it.key(), "light", entry, entry.fileLights);
        if (it.value().is_object() && it.value().contains("name"))
            fail(at / it.key() / "name", "the key names the light it overrides; a name is not allowed here");
        Light light = readLight(it.value(), at / it.key(), static_cast<std::size_t>(found - scene.lights.begin()));
        light.name = it.key();
        light.importedFrom = importIndex;
        *found = light;
    }
}

// Appends each glTF file the scene places, after the scene's own parts, so that their indices
// (and the file's own order) are those of the file, and applies the entry's material overrides.
void resolveImports(SceneDraft& draft, const std::filesystem::path& sceneFile, const ReadScope& scope) {
    Scene& scene = draft.scene;
    std::vector<TextureRequest> overrideTextures;
    for (std::size_t i = 0; i < scene.imports.size(); ++i) {
        SceneImport& entry = scene.imports[i];
        if (entry.file.is_relative()) entry.file = sceneFile.parent_path() / entry.file;
        if (std::optional<std::string> refusal = scope.refusal(entry.file)) fail(draft.importPlaces[i], *refusal);
        const std::size_t first = scene.materials.size();
        const std::size_t firstLight = scene.lights.size();
        try {
            appendGltf(entry.file, entry.transform.objectToWorld(), static_cast<int>(i), scene, scope);
        } catch (const SceneError& error) {
            fail(draft.importPlaces[i], error.what());
        }
        entry.fileMaterials.assign(scene.materials.begin() + static_cast<std::ptrdiff_t>(first), scene.materials.end());
        entry.fileLights.assign(scene.lights.begin() + static_cast<std::ptrdiff_t>(firstLight), scene.lights.end());
        if (const Json* overrides = draft.importLightOverrides[i])
            applyLightOverrides(*overrides, draft.importPlaces[i].parent_pointer() / "lights", entry, static_cast<int>(i),
                                firstLight, scene);
        if (const Json* overrides = draft.importOverrides[i])
            applyMaterialOverrides(*overrides, draft.importPlaces[i].parent_pointer() / "materials", entry, first, scene,
                                   overrideTextures);
    }
    resolveTextures(overrideTextures, sceneFile, scope, scene);
}

} // namespace

Scene loadScene(const std::filesystem::path& path, const ReadScope& scope) {
    if (isGltfFile(path)) return loadGltfScene(path, scope);
    std::string text;
    try {
        text = readInputFile(path, kMaxSceneFileBytes, "scene file");
    } catch (const InputFileError& e) {
        throw oneLineError(e.what());
    }
    try {
        return parseScene(text, path, scope);
    } catch (const std::bad_alloc&) {
        // A document of many small values takes many times its size in memory.
        throw oneLineError(path.string() + ": not enough memory to load the scene (" +
                           std::to_string((text.size() + kMiB - 1) / kMiB) + " MiB on disk)");
    }
}

Scene parseScene(const std::string& jsonText, const std::filesystem::path& sourceName, const ReadScope& scope) {
    const std::string file = sourceName.string();
    try {
        DocumentBuilder builder;
        Json::sax_parse(jsonText, &builder, Json::input_format_t::json, /*strict=*/true);
        SceneDraft draft = readScene(builder.root);
        resolveMeshes(draft, sourceName, scope);
        resolveTextures(draft.textureRequests, sourceName, scope, draft.scene);
        resolveImports(draft, sourceName, scope);
        Scene scene = std::move(draft.scene);
        scene.path = sourceName;
        // Relative to the scene file, as people write them; not normalised, so that ".." means
        // what the file system says even through symbolic links.
        if (!scene.environmentMap.empty() && scene.environmentMap.is_relative())
            scene.environmentMap = sourceName.parent_path() / scene.environmentMap;
        if (!scene.environmentMap.empty())
            if (std::optional<std::string> refusal = scope.refusal(scene.environmentMap)) fail(Pointer("/environment/map"), *refusal);
        return scene;
    } catch (const SyntaxError& error) {
        auto place = [&](std::size_t offset) {
            auto [line, column] = lineAndColumn(jsonText, offset);
            return file + ":" + std::to_string(line) + ":" + std::to_string(column);
        };
        std::string message = place(error.offset) + ": malformed JSON: " + error.what();
        // The end says only that something is missing; where the unclosed value began says what.
        if (error.offset >= jsonText.size()) {
            if (std::optional<UnclosedValue> unclosed = unclosedValue(jsonText)) {
                message += "; " + place(unclosed->offset) + ": unclosed " + unclosed->kind + " begun here";
                if (unclosed->misplacedCloser) {
                    auto [line, column] = lineAndColumn(jsonText, *unclosed->misplacedCloser);
                    message += " (probably: the '" + std::string(1, jsonText[*unclosed->misplacedCloser]) + "' at " +
                               std::to_string(line) + ":" + std::to_string(column) +
                               " closes it by count but is indented as an outer one's)";
                }
            }
        }
        throw oneLineError(message);
    } catch (const PlaceError& error) {
        std::string where = error.where.to_string();
        // The whole document has the empty pointer, which would read as a stray ": ".
        throw oneLineError(file + ": " + (where.empty() ? "" : where + ": ") + error.what());
    }
}

} // namespace ptview
