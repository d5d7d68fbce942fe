#include <ptview/scene/ObjLoader.h>

#include <ptview/io/InputFile.h>
#include <ptview/scene/TextureLoader.h>

#include <tiny_obj_loader.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <istream>
#include <iterator>
#include <map>
#include <new>
#include <streambuf>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <utility>

// tinyobjloader's streaming reader (LoadObjWithCallback) is used rather than tinyobj::ObjReader,
// which does its own checking and gets three things wrong for us (2.0.0rc10):
//   - a `usemtl` name that no MTL entry defines becomes material -1, so with a missing MTL file
//     every face loses its slot name;
//   - an index past the end is only a warning, carrying the number of the file's LAST line, and the
//     face is kept with the bad index (a quad with one is dropped without a count);
//   - like every tinyobjloader reader it reads "nan", "inf" or a missing field as 0.
// The streaming reader hands over each record as it reads it, with the raw indices and the usemtl
// name, so the checks below see exactly what the file says and can name the line.

namespace ptview {
namespace {

bool isBlank(char c) { return c == ' ' || c == '\t'; }
bool isLineEnd(char c) { return c == '\n' || c == '\r'; }

template <int N>
bool isFinite(const glm::vec<N, float>& v) {
    for (int i = 0; i < N; ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}

std::string counted(std::size_t count, const char* noun) {
    return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

// --- Bytes and lines --------------------------------------------------------------------------

// OBJ files of real scans run to a few GiB; past this one a mistake (or a device) is likelier
// than a mesh, and the memory for a mesh that size would run out anyway.
constexpr std::uintmax_t kMaxObjFileBytes = 8192 * kMiB;
// A material library is a few lines per material.
constexpr std::uintmax_t kMaxMtlFileBytes = 64 * kMiB;

// tinyobjloader (2.0.0rc10) reads a number's exponent into an int and checks for overflow one
// digit too late: "1e2147483648" overflows it, which is undefined behaviour, and a longer exponent
// fails the parse, so that the number reads as 0 without a word (found by tests/fuzz; see
// tests/FuzzRegressionTest.cpp). As a float such a number is infinite or 0 anyway, so before the
// parser sees them, exponents of ten or more digits (leading zeros aside) are rewritten in place as
// 999999999, zero-padded to the same length so that offsets and line numbers stay: the parser
// reads that safely, with the same result.
void clampHugeExponents(std::string& bytes) {
    auto isDigit = [](char c) { return c >= '0' && c <= '9'; };
    const std::size_t size = bytes.size();
    for (std::size_t e = bytes.find_first_of("eE"); e != std::string::npos; e = bytes.find_first_of("eE", e + 1)) {
        // Only in a number: a field of an optional sign, then digits and dots up to the 'e'.
        std::size_t start = e;
        while (start > 0 && (isDigit(bytes[start - 1]) || bytes[start - 1] == '.')) --start;
        if (start == e) continue;
        if (start > 0 && (bytes[start - 1] == '+' || bytes[start - 1] == '-')) --start;
        if (start > 0 && !isBlank(bytes[start - 1]) && !isLineEnd(bytes[start - 1])) continue;
        std::size_t first = e + 1;
        if (first < size && (bytes[first] == '+' || bytes[first] == '-')) ++first;
        while (first < size && bytes[first] == '0') ++first;
        std::size_t end = first;
        while (end < size && isDigit(bytes[end])) ++end;
        if (end - first < 10) continue;
        std::fill(bytes.begin() + std::ptrdiff_t(first), bytes.begin() + std::ptrdiff_t(end - 9), '0');
        std::fill(bytes.begin() + std::ptrdiff_t(end - 9), bytes.begin() + std::ptrdiff_t(end), '9');
    }
}

// Editors on Windows start UTF-8 text with a byte-order mark, which tinyobjloader takes for part
// of the first keyword: a first line "v 0 0 0" was skipped without a word, and every index after
// it pointed one vertex further. The mark is blanked (three spaces, so offsets stay), and the
// reader skips blanks before a keyword.
void blankByteOrderMark(std::string& bytes) {
    if (bytes.compare(0, 3, "\xEF\xBB\xBF") == 0) bytes.replace(0, 3, "   ");
}

// An input stream over bytes already in memory (std::istringstream would copy 80 MB) that also
// says how far reading has got. tinyobjloader calls back as soon as it has read a record's line,
// so at a callback that position is the end of the record's line.
class MemoryBuffer : public std::streambuf {
public:
    explicit MemoryBuffer(std::string& bytes) {
        setg(bytes.data(), bytes.data(), bytes.data() + bytes.size());
    }
    std::size_t consumed() const { return static_cast<std::size_t>(gptr() - eback()); }
};

// The text of the line whose end (just past its line break, or the end of the file) is `end`.
// Line breaks are \n, \r\n or a lone \r, as tinyobjloader reads them.
std::string_view lineEndingAt(std::string_view bytes, std::size_t end) {
    std::size_t textEnd = end;
    if (textEnd > 0 && bytes[textEnd - 1] == '\n') --textEnd;
    if (textEnd > 0 && bytes[textEnd - 1] == '\r') --textEnd;
    std::size_t begin = textEnd;
    while (begin > 0 && !isLineEnd(bytes[begin - 1])) --begin;
    return bytes.substr(begin, textEnd - begin);
}

// The 1-based number of the line that ends at `end`. Only messages need it, so counting from the
// start of the file each time costs nothing on the way that succeeds.
std::size_t lineNumberEndingAt(std::string_view bytes, std::size_t end) {
    const std::size_t begin = static_cast<std::size_t>(lineEndingAt(bytes, end).data() - bytes.data());
    std::size_t line = 1;
    for (std::size_t i = 0; i < begin; ++i) {
        if (bytes[i] == '\n') {
            ++line;
        } else if (bytes[i] == '\r') {
            if (i + 1 < begin && bytes[i + 1] == '\n') ++i;
            ++line;
        }
    }
    return line;
}

// How many records start with `keyword` (a one-letter one: `l` or `p`). The streaming reader skips
// them without a callback; the letters are rare in OBJ text, so memchr visits few candidates.
std::size_t countRecords(std::string_view bytes, char keyword) {
    const char* begin = bytes.data();
    const char* end = begin + bytes.size();
    std::size_t count = 0;
    for (const char* at = begin;
         (at = static_cast<const char*>(std::memchr(at, keyword, static_cast<std::size_t>(end - at))));
         ++at) {
        if (at + 1 == end || !isBlank(at[1])) continue;
        const char* before = at;
        while (before > begin && isBlank(before[-1])) --before;
        if (before == begin || isLineEnd(before[-1])) ++count;
    }
    return count;
}

// Whether a record's first `required` fields after its keyword, and any present up to `most`,
// are numbers. tinyobjloader reads anything else as 0 without a word ("nan", "inf", a field lost
// where a file was cut short), which would put a vertex at the origin instead of leaving it out.
// A '#' ends the fields: some exporters put a comment after the numbers.
bool fieldsAreNumbers(std::string_view line, int required, int most) {
    std::size_t at = 0;
    auto skipBlanks = [&] {
        while (at < line.size() && isBlank(line[at])) ++at;
    };
    skipBlanks();
    while (at < line.size() && !isBlank(line[at])) ++at; // the keyword
    for (int field = 0; field < most; ++field) {
        skipBlanks();
        if (at == line.size() || line[at] == '#') return field >= required;
        bool digit = false;
        for (; at < line.size() && !isBlank(line[at]); ++at) {
            const char c = line[at];
            if (c >= '0' && c <= '9')
                digit = true;
            else if (c != '+' && c != '-' && c != '.' && c != 'e' && c != 'E')
                return false;
        }
        if (!digit) return false;
    }
    return true;
}

// The text of corner `corner` (0-based) of a face record, split the way tinyobjloader splits it
// (its reader reads "1/2/3/4" as the corner "1/2/3" and then a corner "/4"), for messages.
std::string_view cornerText(std::string_view line, int corner) {
    std::size_t at = 0;
    auto inside = [&] { return at < line.size() && line[at] != '\0'; };
    auto skipBlanks = [&] {
        while (inside() && isBlank(line[at])) ++at;
    };
    auto skipNumber = [&] {
        while (inside() && !isBlank(line[at]) && line[at] != '/') ++at;
    };
    skipBlanks();
    at += 1; // the keyword `f`
    skipBlanks();
    for (int k = 0; inside(); ++k) {
        const std::size_t begin = at;
        skipNumber();
        if (inside() && line[at] == '/') {
            ++at;
            if (inside() && line[at] == '/') {
                ++at;
                skipNumber();
            } else {
                skipNumber();
                if (inside() && line[at] == '/') {
                    ++at;
                    skipNumber();
                }
            }
        }
        if (k == corner) return line.substr(begin, at - begin);
        skipBlanks();
    }
    return {};
}

// tinyobjloader's messages, one per line, each given our file name.
void appendMessages(const std::string& file, const std::string& messages, std::vector<std::string>& out) {
    std::size_t begin = 0;
    while (begin < messages.size()) {
        std::size_t end = messages.find('\n', begin);
        if (end == std::string::npos) end = messages.size();
        std::string_view line(messages.data() + begin, end - begin);
        while (!line.empty() && (isBlank(line.back()) || line.back() == '\r' || line.back() == '.'))
            line.remove_suffix(1);
        while (!line.empty() && (isBlank(line.front()) || line.front() == '.')) line.remove_prefix(1);
        if (!line.empty()) out.push_back(file + ": " + std::string(line));
        begin = end + 1;
    }
}

// --- Materials --------------------------------------------------------------------------------

MeshMaterial toMeshMaterial(const tinyobj::material_t& entry) {
    MeshMaterial material;
    material.name = entry.name;
    material.diffuse = {entry.diffuse[0], entry.diffuse[1], entry.diffuse[2]};
    material.specular = {entry.specular[0], entry.specular[1], entry.specular[2]};
    material.emission = {entry.emission[0], entry.emission[1], entry.emission[2]};
    material.shininess = entry.shininess;
    material.ior = entry.ior;
    material.dissolve = entry.dissolve; // tinyobjloader has already turned Tr into 1 - Tr, and lets d win
    material.illum = entry.illum;
    return material;
}

// A value that is not a finite number (NaN, or an overflow such as "Ke 1e39") cannot become a
// colour or an index of refraction; it is put back to MeshMaterial's default, with a warning naming
// the MTL file, the material and the key, as a vertex with such a coordinate is dropped.
void repairNonFiniteValues(MeshMaterial& material, const std::string& mtlFile, std::vector<std::string>& warnings) {
    const MeshMaterial defaults;
    auto warn = [&](const char* key) {
        warnings.push_back(mtlFile + ": material \"" + material.name + "\": " + key +
                           " is not a finite number; using the default");
    };
    auto repairColour = [&](glm::vec3& value, const glm::vec3& fallback, const char* key) {
        if (std::isfinite(value.x) && std::isfinite(value.y) && std::isfinite(value.z)) return;
        value = fallback;
        warn(key);
    };
    auto repairNumber = [&](float& value, float fallback, const char* key) {
        if (std::isfinite(value)) return;
        value = fallback;
        warn(key);
    };
    repairColour(material.diffuse, defaults.diffuse, "Kd");
    repairColour(material.specular, defaults.specular, "Ks");
    repairColour(material.emission, defaults.emission, "Ke");
    repairNumber(material.shininess, defaults.shininess, "Ns");
    repairNumber(material.ior, defaults.ior, "Ni");
    repairNumber(material.dissolve, defaults.dissolve, "d (or Tr)");
    auto repairOptional = [&](std::optional<float>& value, const char* key) {
        if (!value || std::isfinite(*value)) return;
        value.reset();
        warn(key);
    };
    repairOptional(material.roughness, "Pr");
    repairOptional(material.metallic, "Pm");
}

// The texture keys ptview reads, by the name MtlReader files them under; empty for any other key.
// tinyobjloader reads map_Bump, map_bump and bump as one map.
std::string_view readTextureKey(std::string_view key) {
    if (key == "map_Kd" || key == "map_Ke" || key == "map_Pr" || key == "map_Pm" || key == "norm") return key;
    if (key == "bump" || key == "map_Bump" || key == "map_bump") return "bump";
    return {};
}

// Looks for each `mtllib` file in the OBJ's directory (tinyobjloader's own file reader splits its
// search path at ':' and, for an OBJ path without a directory, looks nowhere), and words what
// happens in our terms, naming the MTL file.
class MtlReader : public tinyobj::MaterialReader {
public:
    MtlReader(std::filesystem::path directory, std::string objFile, TriangleMesh& mesh,
              std::vector<std::string>& warnings, const ReadScope& scope, TextureBudget* sceneBudget)
        : directory_(std::move(directory)), objFile_(std::move(objFile)), mesh_(mesh), warnings_(warnings), scope_(scope),
          sceneBudget_(sceneBudget) {}

    bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* nameToIndex, std::string* /*warn*/,
                    std::string* /*err*/) override {
        const std::filesystem::path path = directory_ / name;
        // Outside what the scene may read: not even whether it exists is looked at.
        if (std::optional<std::string> refusal = scope_.refusal(path)) {
            warnings_.push_back(objFile_ + ": material library not read: " + *refusal + "; its faces keep their material names");
            return false;
        }
        std::error_code ignored;
        if (!std::filesystem::exists(path, ignored)) {
            warnings_.push_back(objFile_ + ": material library " + name + " not found (looked for " +
                                path.string() + "); its faces keep their material names");
            return false;
        }
        // A library that is there but unusable (a directory, a device, too large) is as good as
        // missing, with the reason.
        std::string bytes;
        try {
            bytes = readInputFile(path, kMaxMtlFileBytes, "material library");
        } catch (const InputFileError& e) {
            warnings_.push_back(std::string(e.what()) + "; the faces of " + objFile_ + " keep their material names");
            return false;
        }
        blankByteOrderMark(bytes);
        clampHugeExponents(bytes);
        MemoryBuffer buffer(bytes);
        std::istream stream(&buffer);
        const std::size_t before = materials->size();
        std::string mtlWarnings, mtlErrors;
        tinyobj::LoadMtl(nameToIndex, materials, &stream, &mtlWarnings, &mtlErrors);
        appendMessages(path.string(), mtlWarnings + mtlErrors, warnings_);
        // tinyobjloader ends every MTL with the material it was filling, so a file without a
        // `newmtl` still yields one, unnamed: that one is dropped, not offered as a material.
        if (checkMtlLines(bytes, path) == 0) {
            warnings_.push_back(path.string() + ": defines no materials (no newmtl line)");
            for (std::size_t i = before; i < materials->size(); ++i) nameToIndex->erase((*materials)[i].name);
            materials->resize(before);
        }
        // tinyobjloader keeps one material per named newmtl, so the lines line up with its entries
        // unless a newmtl names nothing; then messages name the file alone.
        const bool linesKnown = materials->size() - before == keyLines_.size();
        for (std::size_t i = before; i < materials->size(); ++i) {
            const tinyobj::material_t& entry = (*materials)[i];
            MeshMaterial material = toMeshMaterial(entry);
            const KeyLines noLines;
            const KeyLines& lines = linesKnown ? keyLines_[i - before] : noLines;
            if (lines.count("Pr")) material.roughness = entry.roughness;
            if (lines.count("Pm")) material.metallic = entry.metallic;
            // A map multiplies its factor (the MTL convention); a factor left out would make it
            // black, so an entry with map_Kd or map_Ke but no Kd or Ke gets a factor of 1.
            if (!entry.diffuse_texname.empty() && linesKnown && !lines.count("Kd")) material.diffuse = glm::vec3(1.0f);
            if (!entry.emissive_texname.empty() && linesKnown && !lines.count("Ke")) material.emission = glm::vec3(1.0f);
            repairNonFiniteValues(material, path.string(), warnings_);
            auto map = [&](const std::string& texname, const tinyobj::texture_option_t& options, const char* key,
                           MeshTextureMap& out) {
                if (texname.empty()) return;
                auto line = lines.find(key);
                const std::string place =
                    path.string() + (line == lines.end() ? std::string() : ":" + std::to_string(line->second.first));
                const std::string keyText = line == lines.end() ? std::string(key) : line->second.second;
                out = readTextureMap(texname, options, place, keyText, path.parent_path());
            };
            map(entry.diffuse_texname, entry.diffuse_texopt, "map_Kd", material.diffuseMap);
            map(entry.emissive_texname, entry.emissive_texopt, "map_Ke", material.emissionMap);
            map(entry.roughness_texname, entry.roughness_texopt, "map_Pr", material.roughnessMap);
            map(entry.metallic_texname, entry.metallic_texopt, "map_Pm", material.metallicMap);
            if (!entry.normal_texname.empty())
                map(entry.normal_texname, entry.normal_texopt, "norm", material.normalMap);
            else
                map(entry.bump_texname, entry.bump_texopt, "bump", material.normalMap);
            mesh_.fileMaterials.push_back(std::move(material));
        }
        return true;
    }

private:
    // Warns, naming the file and line, where tinyobjloader would read on without a word: a value
    // that is not a number ("Kd abc" reads as 0) and a texture map that is not there. Returns how
    // many `newmtl` lines there are.
    std::size_t checkMtlLines(std::string_view bytes, const std::filesystem::path& path) {
        struct NumericKey {
            const char* key;
            int required, most;
        };
        static const NumericKey kNumericKeys[] = {{"Ka", 1, 3}, {"Kd", 1, 3}, {"Ks", 1, 3}, {"Ke", 1, 3},
                                                  {"Kt", 1, 3}, {"Tf", 1, 3}, {"Ns", 1, 1}, {"Ni", 1, 1},
                                                  {"d", 1, 1},  {"Tr", 1, 1}, {"illum", 1, 1},
                                                  {"Pr", 1, 1}, {"Pm", 1, 1}};
        std::size_t materials = 0, lineNumber = 0, begin = 0;
        keyLines_.clear();
        while (begin < bytes.size()) {
            std::size_t end = begin;
            while (end < bytes.size() && !isLineEnd(bytes[end])) ++end;
            ++lineNumber;
            std::string_view line = bytes.substr(begin, end - begin);
            begin = end + (end + 1 < bytes.size() && bytes[end] == '\r' && bytes[end + 1] == '\n' ? 2 : 1);
            std::size_t at = 0;
            while (at < line.size() && isBlank(line[at])) ++at;
            line.remove_prefix(at);
            std::size_t keyEnd = 0;
            while (keyEnd < line.size() && !isBlank(line[keyEnd])) ++keyEnd;
            const std::string_view key = line.substr(0, keyEnd);
            std::string_view rest = line.substr(keyEnd);
            while (!rest.empty() && isBlank(rest.front())) rest.remove_prefix(1);
            while (!rest.empty() && isBlank(rest.back())) rest.remove_suffix(1);
            const std::string place = path.string() + ":" + std::to_string(lineNumber) + ": ";
            if (key == "newmtl") {
                ++materials;
                keyLines_.emplace_back();
                continue;
            }
            const std::string_view textureKey = readTextureKey(key);
            const bool factorKey = key == "Kd" || key == "Ke" || key == "Pr" || key == "Pm";
            if (!keyLines_.empty() && (!textureKey.empty() || factorKey))
                keyLines_.back()[std::string(textureKey.empty() ? key : textureKey)] = {lineNumber, std::string(key)};
            for (const NumericKey& numeric : kNumericKeys)
                if (key == numeric.key && !fieldsAreNumbers(line, numeric.required, numeric.most))
                    warnings_.push_back(place + std::string(key) +
                                        (rest.empty() ? std::string(" has no value")
                                                      : " \"" + std::string(rest) + "\" is not a number") +
                                        "; it reads as 0");
            // The maps ptview reads are looked for when they are decoded (readTextureMap).
            const bool read = !textureKey.empty();
            if (key == "map_Ns") {
                warnings_.push_back(place + "map_Ns (a shininess map) is not read; roughness maps are map_Pr");
                continue;
            }
            if (!read && (key.substr(0, 4) == "map_" || key == "bump" || key == "disp" || key == "decal" || key == "refl")) {
                // The file name is the last word: options such as "-s 1 1 1" come before it.
                const std::size_t lastBlank = rest.find_last_of(" \t");
                const std::string_view name = lastBlank == std::string_view::npos ? rest : rest.substr(lastBlank + 1);
                const std::filesystem::path texture = path.parent_path() / std::string(name);
                std::error_code ignored;
                if (name.empty())
                    warnings_.push_back(place + std::string(key) + " names no file");
                else if (!scope_.refusal(texture) && !std::filesystem::exists(texture, ignored))
                    warnings_.push_back(place + std::string(key) + " " + std::string(name) + " not found (looked for " +
                                        texture.string() +
                                        "); ptview does not read this map, but the model may need it");
            }
        }
        return materials;
    }

    // A texture map's file, options and decoded image. A file that is missing or does not decode
    // is a warning naming the MTL line; the map keeps its file name (so the material still becomes
    // one that takes textures) with no image, and renders with its factor alone.
    MeshTextureMap readTextureMap(const std::string& texname, const tinyobj::texture_option_t& options,
                                  const std::string& place, const std::string& key,
                                  const std::filesystem::path& directory) {
        MeshTextureMap map;
        map.file = directory / std::filesystem::u8path(texname);
        map.place = place;
        // MTL's -s and -o act on OBJ's coordinates (v up); the model's v is 1 - v (Texture.h), so
        // v_model' = 1 - (s (1 - v_model) + o) = s v_model + (1 - s - o).
        const glm::vec2 scale(options.scale[0], options.scale[1]);
        const glm::vec2 offset(options.origin_offset[0], options.origin_offset[1]);
        if (std::isfinite(scale.x) && std::isfinite(scale.y) && std::isfinite(offset.x) && std::isfinite(offset.y)) {
            map.scale = scale;
            map.offset = {offset.x, 1.0f - scale.y - offset.y};
        } else {
            warnings_.push_back(place + ": " + key + ": -s or -o is not a finite number; using none");
        }
        map.clamp = options.clamp;
        map.bumpMultiplier = std::isfinite(options.bump_multiplier) ? options.bump_multiplier : 1.0f;
        const std::string why = "; rendered with the factor alone";
        if (std::optional<std::string> refusal = scope_.refusal(map.file)) {
            warnings_.push_back(place + ": " + key + " not read: " + *refusal + why);
            return map;
        }
        std::error_code ignored;
        if (!std::filesystem::exists(map.file, ignored)) {
            warnings_.push_back(place + ": " + key + " " + texname + " not found (looked for " + map.file.string() +
                                ")" + why);
            return map;
        }
        const std::string file = map.file.string();
        auto cached = decoded_.find(file);
        if (cached != decoded_.end()) {
            map.image = cached->second;
            if (!map.image) warnings_.push_back(place + ": " + key + " " + texname + ": see above" + why);
            return map;
        }
        // The maps share the scene load's texture budget (TextureLoader.h), or, for an OBJ read
        // alone, one of their own: what those decoded so far take.
        std::uint64_t spent = 0;
        for (const auto& [decodedFile, image] : decoded_)
            if (image) spent += decodedBytes({image->width, image->height});
        TextureBudget ownBudget(spent);
        try {
            map.image = loadTextureImage(map.file, sceneBudget_ ? sceneBudget_ : &ownBudget);
        } catch (const TextureError& e) {
            warnings_.push_back(place + ": " + key + " " + e.what() + why); // e names the file
        }
        decoded_.emplace(file, map.image);
        return map;
    }

    // For each newmtl of the file being read, in order: the line of each texture key it gives
    // (readTextureKey's names) and of the factors that go with them (Kd, Ke, Pr, Pm), with the
    // key as written.
    using KeyLines = std::map<std::string, std::pair<std::size_t, std::string>>;
    std::vector<KeyLines> keyLines_;
    // Each image file decodes once per OBJ, however many maps name it; null: it did not decode.
    std::map<std::string, std::shared_ptr<const TextureImage>> decoded_;

    std::filesystem::path directory_;
    std::string objFile_;
    TriangleMesh& mesh_;
    std::vector<std::string>& warnings_;
    const ReadScope& scope_;
    TextureBudget* sceneBudget_; // null: the maps of this OBJ alone are budgeted
};

// --- Records to triangles ---------------------------------------------------------------------

// Builds the mesh from tinyobjloader's callbacks. Triangles are first stored with the file's own
// (0-based) indices; what needs the whole file (forward references, which vertices are usable) is
// settled in finish(). Every per-record step is constant work, so loading stays linear.
class ObjBuilder {
public:
    ObjBuilder(std::string file, std::string_view bytes, const MemoryBuffer& stream, TriangleMesh& mesh)
        : file_(std::move(file)), bytes_(bytes), stream_(stream), mesh_(mesh) {
        mesh_.materialSlots.assign(1, "");
        slotOfName_.emplace("", 0);
    }

    tinyobj::callback_t callbacks() {
        tinyobj::callback_t calls;
        calls.vertex_cb = [](void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z,
                             tinyobj::real_t) { static_cast<ObjBuilder*>(self)->addPosition(x, y, z); };
        calls.normal_cb = [](void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z) {
            static_cast<ObjBuilder*>(self)->addNormal(x, y, z);
        };
        calls.texcoord_cb = [](void* self, tinyobj::real_t u, tinyobj::real_t v, tinyobj::real_t) {
            static_cast<ObjBuilder*>(self)->addTexcoord(u, v);
        };
        calls.index_cb = [](void* self, tinyobj::index_t* corners, int count) {
            static_cast<ObjBuilder*>(self)->addFace(corners, count);
        };
        calls.usemtl_cb = [](void* self, const char* name, int) {
            static_cast<ObjBuilder*>(self)->useMaterial(name);
        };
        return calls;
    }

    // Settles indices, drops what cannot be drawn and reports it. Throws MeshError.
    void finish(std::size_t polylines, std::size_t points, std::vector<std::string>& warnings);

    // The first error met while reading, if any: tinyobjloader reads on after a callback, so
    // callbacks note it here instead of throwing through the library.
    const std::string& error() const { return error_; }

private:
    // Where a record's line ends, for line numbers in messages.
    std::size_t here() const { return stream_.consumed(); }
    std::string at(std::size_t end) const {
        return file_ + ":" + std::to_string(lineNumberEndingAt(bytes_, end));
    }
    // "FILE:LINE: face N, corner K ("1/2/3")": the corner quoted as written, since an index that
    // does not fit an int reaches us as some other number.
    std::string cornerPlace(std::size_t end, std::size_t face, int corner) const {
        return at(end) + ": face " + std::to_string(face) + ", corner " + std::to_string(corner + 1) +
               " (\"" + std::string(cornerText(lineEndingAt(bytes_, end), corner)) + "\")";
    }
    void fail(int corner, const std::string& reason) {
        if (error_.empty()) error_ = cornerPlace(here(), faces_, corner) + ": " + reason;
    }

    // One attribute kind's indices (positions, normals or texture coordinates): for each record in
    // the file, its index among the usable ones we keep, or -1 if it is not usable.
    struct Attribute {
        const char* noun;
        std::vector<std::int32_t> kept;
        std::size_t unusable = 0;
        std::size_t firstUnusableEnd = 0; // where its line ends
        std::int64_t largestUsed = -1;    // the largest index a face uses, and where
        std::size_t largestUsedFace = 0;
        int largestUsedCorner = 0;
        std::size_t largestUsedEnd = 0;

        void add(bool usable, std::size_t keptCount, std::size_t end) {
            if (usable) {
                kept.push_back(static_cast<std::int32_t>(keptCount));
            } else {
                if (unusable++ == 0) firstUnusableEnd = end;
                kept.push_back(-1);
            }
        }
    };

    void addPosition(float x, float y, float z) {
        const glm::vec3 p(x, y, z);
        const bool usable = isFinite(p) && fieldsAreNumbers(record(), 3, 3);
        positions_.add(usable, mesh_.positions.size(), here());
        if (usable) mesh_.positions.push_back(p);
    }

    void addNormal(float x, float y, float z) {
        // In double: in float, a component above about 1.8e19 overflows the squared length to
        // infinity, and n / length then makes a valid direction the zero vector, which passes as
        // finite (found by tests/fuzz; ObjLoader.HugeNormalComponentsStillNormalize).
        const glm::dvec3 n(x, y, z);
        const double length = glm::length(n);
        const glm::vec3 unit(n / length);
        const bool usable = length > 0.0 && isFinite(unit) && fieldsAreNumbers(record(), 3, 3);
        normals_.add(usable, mesh_.normals.size(), here());
        if (usable) mesh_.normals.push_back(unit);
    }

    void addTexcoord(float u, float v) {
        // OBJ counts v up from the image's bottom row; the model counts it down from the top (Texture.h).
        const glm::vec2 uv(u, 1.0f - v);
        const bool usable = isFinite(uv) && fieldsAreNumbers(record(), 1, 2);
        texcoords_.add(usable, mesh_.texcoords.size(), here());
        if (usable) mesh_.texcoords.push_back(uv);
    }

    std::string_view record() const { return lineEndingAt(bytes_, here()); }

    // An OBJ index as the streaming reader passes it (1-based, negative counting back from the last
    // one defined so far, 0 for none given) made 0-based; -1 for none. Past-the-end indices are
    // only noted here, since the vertex may still come (a forward reference).
    std::int64_t resolve(int index, Attribute& attribute, int corner) {
        if (index == 0) return -1;
        std::int64_t resolved =
            index > 0 ? std::int64_t(index) - 1 : std::int64_t(attribute.kept.size()) + index;
        if (resolved < 0) {
            fail(corner, std::string(attribute.noun) + " index " + std::to_string(index) +
                             " reaches back past the first " + attribute.noun + " (" +
                             std::to_string(attribute.kept.size()) + " defined before this face)");
            return -1;
        }
        if (resolved > attribute.largestUsed) {
            attribute.largestUsed = resolved;
            attribute.largestUsedFace = faces_;
            attribute.largestUsedCorner = corner;
            attribute.largestUsedEnd = here();
        }
        return resolved;
    }

    void addFace(const tinyobj::index_t* corners, int count) {
        ++faces_;
        if (!error_.empty()) return;
        if (!indicesFitAnInt(count)) return;
        if (count < 3) {
            if (shortFaces_++ == 0) firstShortFaceEnd_ = here();
            return;
        }
        // Corner 0 and its attributes, then a fan: OBJ polygons are convex and planar, and a fan
        // from any corner covers such a polygon exactly.
        std::int64_t position[3], normal[3], texcoord[3];
        for (int k = 0; k < count; ++k) {
            if (corners[k].vertex_index == 0) {
                // The reader takes a comment after a face's corners for more corners (with index 0).
                if (cornerText(record(), k).substr(0, 1) == "#") {
                    if (k < 3 && shortFaces_++ == 0) firstShortFaceEnd_ = here();
                    return;
                }
                fail(k, "no position index (OBJ counts from 1)");
                return;
            }
            const int slot = k < 2 ? k : 2;
            position[slot] = resolve(corners[k].vertex_index, positions_, k);
            normal[slot] = resolve(corners[k].normal_index, normals_, k);
            texcoord[slot] = resolve(corners[k].texcoord_index, texcoords_, k);
            if (!error_.empty()) return;
            if (k < 2) continue;
            MeshTriangle triangle;
            for (int c = 0; c < 3; ++c) {
                triangle.position[c] = static_cast<std::uint32_t>(position[c]);
                triangle.normal[c] = static_cast<std::int32_t>(normal[c]);
                triangle.texcoord[c] = static_cast<std::int32_t>(texcoord[c]);
            }
            triangle.materialSlot = slot_;
            mesh_.triangles.push_back(triangle);
            // The next triangle of the fan shares corner 0 and this triangle's last corner.
            position[1] = position[2];
            normal[1] = normal[2];
            texcoord[1] = texcoord[2];
        }
    }

    // tinyobjloader reads an index as atoi does, so one beyond the int range comes through as some
    // other number: "4294967299" as 3, "99999999999999999999" as -1, a valid index either way. The
    // digits are read again here and such an index refused. Only a line with a run of ten digits
    // or more can hold one, so the common line costs one scan.
    bool indicesFitAnInt(int count) {
        const std::string_view line = record();
        std::size_t run = 0, longest = 0;
        for (char c : line) {
            run = (c >= '0' && c <= '9') ? run + 1 : 0;
            longest = std::max(longest, run);
        }
        if (longest < 10) return true;
        static const char* const kNouns[3] = {"position", "texture coordinate", "normal"};
        for (int k = 0; k < count; ++k) {
            std::string_view corner = cornerText(line, k);
            if (corner.substr(0, 1) == "#") break; // a comment after the corners
            for (int field = 0; field < 3 && !corner.empty(); ++field) {
                const std::size_t slash = corner.find('/');
                std::string_view digits = corner.substr(0, slash);
                corner = slash == std::string_view::npos ? std::string_view() : corner.substr(slash + 1);
                if (!digits.empty() && digits[0] == '+') digits.remove_prefix(1);
                long long value = 0;
                const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
                const bool tooLarge = ec == std::errc::result_out_of_range ||
                                      (ec == std::errc() && (value > INT_MAX || value < -INT_MAX));
                if (!tooLarge || end == digits.data()) continue;
                fail(k, std::string(kNouns[field]) + " index " + std::string(digits) +
                            " does not fit a 32-bit integer (at most 2147483647)");
                return false;
            }
        }
        return true;
    }

    void useMaterial(const char* text) {
        std::string_view name(text);
        while (!name.empty() && (isBlank(name.back()) || name.back() == '\r')) name.remove_suffix(1);
        while (!name.empty() && isBlank(name.front())) name.remove_prefix(1);
        auto [entry, added] = slotOfName_.emplace(std::string(name), int(mesh_.materialSlots.size()));
        if (added) mesh_.materialSlots.push_back(entry->first);
        slot_ = entry->second;
    }

    void checkRange(const Attribute& attribute) const {
        if (attribute.largestUsed < std::int64_t(attribute.kept.size())) return;
        throw MeshError(
            cornerPlace(attribute.largestUsedEnd, attribute.largestUsedFace, attribute.largestUsedCorner) +
            ": " + attribute.noun + " index " + std::to_string(attribute.largestUsed + 1) +
            " is out of range (the file defines " + counted(attribute.kept.size(), attribute.noun) + ")");
    }

    std::string file_;
    std::string_view bytes_;
    const MemoryBuffer& stream_;
    TriangleMesh& mesh_;
    std::string error_;

    Attribute positions_{"position", {}};
    Attribute normals_{"normal", {}};
    Attribute texcoords_{"texture coordinate", {}};
    std::size_t faces_ = 0;
    std::size_t shortFaces_ = 0;
    std::size_t firstShortFaceEnd_ = 0;
    std::unordered_map<std::string, int> slotOfName_;
    int slot_ = 0;
};

void ObjBuilder::finish(std::size_t polylines, std::size_t points, std::vector<std::string>& warnings) {
    if (!error_.empty()) throw MeshError(error_);
    checkRange(positions_);
    checkRange(normals_);
    checkRange(texcoords_);

    // Tallies of what is dropped, for one warning each instead of one per triangle.
    std::size_t unusableVertex = 0, zeroArea = 0, flatCorners = 0, bareCorners = 0;
    std::size_t kept = 0;
    for (MeshTriangle triangle : mesh_.triangles) {
        std::int32_t p[3];
        for (int c = 0; c < 3; ++c) p[c] = positions_.kept[triangle.position[c]];
        if (p[0] < 0 || p[1] < 0 || p[2] < 0) {
            ++unusableVertex;
            continue;
        }
        // A zero-area triangle covers no surface, so leaving it out cannot open a hole in a closed
        // mesh; kept, it would give the BVH and the shading a normal made from 0/0. Only exact
        // zeros count: a sliver of a finely tessellated mesh is real surface.
        const glm::vec3 a = mesh_.positions[p[0]];
        const glm::vec3 b = mesh_.positions[p[1]];
        const glm::vec3 c = mesh_.positions[p[2]];
        if (p[0] == p[1] || p[1] == p[2] || p[0] == p[2] || glm::cross(b - a, c - a) == glm::vec3(0.0f)) {
            ++zeroArea;
            continue;
        }
        for (int k = 0; k < 3; ++k) {
            triangle.position[k] = static_cast<std::uint32_t>(p[k]);
            if (triangle.normal[k] >= 0) {
                triangle.normal[k] = normals_.kept[triangle.normal[k]];
                if (triangle.normal[k] < 0) ++flatCorners;
            }
            if (triangle.texcoord[k] >= 0) {
                triangle.texcoord[k] = texcoords_.kept[triangle.texcoord[k]];
                if (triangle.texcoord[k] < 0) ++bareCorners;
            }
        }
        mesh_.triangles[kept++] = triangle;
    }
    const std::size_t fanned = mesh_.triangles.size();
    mesh_.triangles.resize(kept);
    mesh_.triangles.shrink_to_fit();

    auto warn = [&](const std::string& text) { warnings.push_back(file_ + ": " + text); };
    if (polylines > 0 && points > 0)
        warn("skipped " + counted(polylines, "polyline record") + " (l) and " +
             counted(points, "point record") + " (p)");
    else if (polylines > 0)
        warn("skipped " + counted(polylines, "polyline record") + " (l)");
    else if (points > 0)
        warn("skipped " + counted(points, "point record") + " (p)");
    if (shortFaces_ > 0)
        warn("skipped " + counted(shortFaces_, "face") + " with fewer than 3 corners (the first at line " +
             std::to_string(lineNumberEndingAt(bytes_, firstShortFaceEnd_)) + ")");
    if (zeroArea > 0) warn("dropped " + counted(zeroArea, "degenerate triangle") + " (zero area)");
    if (unusableVertex > 0)
        warn("dropped " + counted(unusableVertex, "triangle") +
             " using a vertex whose coordinates are not finite numbers (the first such vertex at line " +
             std::to_string(lineNumberEndingAt(bytes_, positions_.firstUnusableEnd)) + ")");
    if (flatCorners > 0)
        warn(counted(flatCorners, "triangle corner") +
             " use a normal that is not finite or has zero length (the first at line " +
             std::to_string(lineNumberEndingAt(bytes_, normals_.firstUnusableEnd)) + "); they shade flat");
    if (bareCorners > 0)
        warn(counted(bareCorners, "triangle corner") +
             " use a texture coordinate that is not a finite number (the first at line " +
             std::to_string(lineNumberEndingAt(bytes_, texcoords_.firstUnusableEnd)) + "); they have none");

    if (mesh_.triangles.empty()) {
        if (fanned == 0)
            throw MeshError(file_ + ": no triangles (" +
                            (faces_ == 0 ? std::string("the file has no faces")
                                         : "none of its " + counted(faces_, "face") + " has 3 corners") +
                            ")");
        throw MeshError(file_ + ": no triangles left: of " + std::to_string(fanned) + ", " +
                        std::to_string(zeroArea) + " have zero area and " + std::to_string(unusableVertex) +
                        " use a vertex that is not a finite number");
    }
}


TriangleMesh readObjMesh(const std::filesystem::path& path, MeshLoadReport* report, const ReadScope& scope,
                         TextureBudget* textureBudget) {
    MeshLoadReport unread;
    std::vector<std::string>& warnings = (report ? *report : unread).warnings;
    const std::string file = path.string();

    std::string bytes = readInputFileAs<MeshError>(path, kMaxObjFileBytes, "mesh file");
    blankByteOrderMark(bytes);
    clampHugeExponents(bytes);
    MemoryBuffer buffer(bytes);
    std::istream stream(&buffer);

    TriangleMesh mesh;
    mesh.source = file;
    ObjBuilder builder(file, bytes, buffer, mesh);
    MtlReader mtlReader(path.parent_path(), file, mesh, warnings, scope, textureBudget);
    std::string libraryWarnings, libraryErrors;
    const bool read = tinyobj::LoadObjWithCallback(stream, builder.callbacks(), &builder, &mtlReader,
                                                   &libraryWarnings, &libraryErrors);
    if (!builder.error().empty()) throw MeshError(builder.error());
    if (!read || !libraryErrors.empty()) {
        std::vector<std::string> errors;
        appendMessages(file, libraryErrors, errors);
        throw MeshError(errors.empty() ? file + ": tinyobjloader could not read it" : errors.front());
    }
    // MtlReader has already said, naming the file, which library is missing; this is the same news.
    std::vector<std::string> messages;
    appendMessages(file, libraryWarnings, messages);
    for (std::string& message : messages)
        if (message.find("Failed to load material file") == std::string::npos)
            warnings.push_back(std::move(message));

    builder.finish(countRecords(bytes, 'l'), countRecords(bytes, 'p'), warnings);
    return mesh;
}

} // namespace

TriangleMesh loadObjMesh(const std::filesystem::path& path, MeshLoadReport* report, const ReadScope& scope,
                         TextureBudget* textureBudget) {
    try {
        return readObjMesh(path, report, scope, textureBudget);
    } catch (const std::bad_alloc&) {
        // A mesh larger than memory is a limit of this machine, not a crash: the scene loader and
        // the viewer report it like any other file they cannot use. What was built is freed by now.
        std::error_code ignored;
        const std::uintmax_t size = std::filesystem::file_size(path, ignored);
        throw MeshError(path.string() + ": not enough memory to load it (" +
                        (ignored ? std::string("size unknown") : std::to_string(size / (1024 * 1024)) + " MiB on disk") + ")");
    }
}

} // namespace ptview
