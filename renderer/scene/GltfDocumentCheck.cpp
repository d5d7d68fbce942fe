#include <ptview/scene/GltfDocumentCheck.h>

#include <cctype>
#include <optional>
#include <set>

namespace ptview::gltf {
namespace {

// What we read of an extension, so one marked required is not refused.
const std::set<std::string> kSupportedExtensions = {"KHR_lights_punctual", "KHR_materials_emissive_strength",
                                                    "KHR_materials_ior", "KHR_materials_transmission",
                                                    "KHR_materials_volume", "KHR_texture_transform"};

// URIs are percent-encoded ("my%20model.bin"); tinygltf decodes them the same way.
std::string decodeUri(const std::string& uri) {
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
            out += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

// A URI as messages quote it: short, since it comes from the file.
std::string quotedUri(const std::string& uri) {
    return "\"" + (uri.size() > 80 ? uri.substr(0, 77) + "..." : uri) + "\"";
}

// Why a buffer's or image's URI names no file inside the model's folder by its form alone, before
// any file is looked at; nullopt for a relative reference. glTF files name their resources by
// URIs relative to the file, or data: URIs (glTF 2.0, "URIs"); anything else is refused rather
// than looked for, so that a model cannot make us read /etc/passwd or a network path.
std::optional<std::string> absoluteUriReason(const std::string& uri) {
    const std::string why = ": a glTF file names its buffers and images by URIs relative to its own folder, or data: URIs";
    std::size_t schemeEnd = 0;
    while (schemeEnd < uri.size() && (std::isalnum(static_cast<unsigned char>(uri[schemeEnd])) ||
                                      uri[schemeEnd] == '+' || uri[schemeEnd] == '-' || uri[schemeEnd] == '.'))
        ++schemeEnd;
    if (schemeEnd > 0 && schemeEnd < uri.size() && uri[schemeEnd] == ':' && std::isalpha(static_cast<unsigned char>(uri[0]))) {
        if (schemeEnd == 1) return quotedUri(uri) + " is an absolute path (a drive letter)" + why;
        return quotedUri(uri) + " is an absolute URI (scheme " + uri.substr(0, schemeEnd) + ":)" + why;
    }
    const std::string decoded = decodeUri(uri);
    if (decoded.find('\0') != std::string::npos) return quotedUri(uri) + " holds a NUL character" + why;
    if (!decoded.empty() && (decoded[0] == '/' || decoded[0] == '\\'))
        return quotedUri(uri) + " is an absolute path" + why;
    if (decoded.size() >= 2 && std::isalpha(static_cast<unsigned char>(decoded[0])) && decoded[1] == ':')
        return quotedUri(uri) + " is an absolute path (a drive letter)" + why;
    return std::nullopt;
}

// The bytes a base64 data URI decodes to, from its length alone.
std::uint64_t dataUriBytes(const std::string& uri) {
    std::size_t comma = uri.find(',');
    if (comma == std::string::npos || uri.rfind(";base64", comma) == std::string::npos) return 0;
    std::size_t n = uri.size() - comma - 1;
    std::size_t padding = 0;
    for (std::size_t i = uri.size(); i > comma + 1 && uri[i - 1] == '=' && padding < 2; --i) ++padding;
    return n / 4 * 3 - (n % 4 == 0 ? padding : 0) + (n % 4 == 0 ? 0 : (n % 4) * 3 / 4);
}

std::uint32_t readU32(const std::string& bytes, std::size_t offset) {
    std::uint32_t value = 0;
    for (int i = 3; i >= 0; --i) value = value << 8 | static_cast<unsigned char>(bytes[offset + static_cast<std::size_t>(i)]);
    return value;
}

// A byte count or index the checks below rely on: one that is there but no unsigned integer
// (4.5, -1) would be read one way here and another by tinygltf, so it is refused.
std::uint64_t unsignedOr(const Json& object, const char* key, std::uint64_t fallback, const std::string& where) {
    auto it = object.find(key);
    if (it == object.end()) return fallback;
    if (!it->is_number_unsigned()) fail(where + "/" + key, "expected an unsigned integer");
    return it->get<std::uint64_t>();
}

// No glTF needs more than a few levels (checkNesting).
constexpr int kMaxJsonDepth = 64;

void checkResourceFile(const std::filesystem::path& file, const std::string& where, const char* kind) {
    try {
        checkInputFile(file, kind);
    } catch (const InputFileError& e) {
        fail(where, e.what());
    }
}

} // namespace

bool isDataUri(const std::string& uri) {
    return uri.rfind("data:", 0) == 0;
}

std::filesystem::path resourcePath(const std::filesystem::path& gltfFile, const std::string& uri,
                                   const ReadScope& modelScope, const std::string& where) {
    if (std::optional<std::string> reason = absoluteUriReason(uri)) fail(where, *reason);
    std::filesystem::path resolved = gltfFile.parent_path() / std::filesystem::u8path(decodeUri(uri));
    if (std::optional<std::string> refusal = modelScope.refusal(resolved)) fail(where, *refusal);
    return resolved;
}

GlbChunks splitGlb(const std::string& bytes) {
    constexpr std::uint32_t kJsonChunk = 0x4E4F534A; // "JSON"
    constexpr std::uint32_t kBinChunk = 0x004E4942;  // "BIN\0"
    if (bytes.size() < 20)
        fail("", "truncated .glb: " + std::to_string(bytes.size()) + " bytes, less than its header and first chunk header (20)");
    if (bytes.compare(0, 4, "glTF") != 0) fail("", "not a .glb file (it does not begin with \"glTF\")");
    if (readU32(bytes, 4) != 2) fail("", "a .glb of container version " + std::to_string(readU32(bytes, 4)) + " (only 2 is read)");
    std::uint64_t length = readU32(bytes, 8);
    if (length > bytes.size())
        fail("", "truncated .glb: its header says " + std::to_string(length) + " bytes, the file has " +
                     std::to_string(bytes.size()));
    std::uint64_t jsonLength = readU32(bytes, 12);
    if (readU32(bytes, 16) != kJsonChunk) fail("", "a .glb whose first chunk is not JSON");
    if (20 + jsonLength > length)
        fail("", "truncated .glb: its JSON chunk of " + std::to_string(jsonLength) + " bytes runs past the end (" +
                     std::to_string(length) + " bytes)");
    GlbChunks chunks;
    chunks.json = bytes.substr(20, jsonLength);
    std::uint64_t next = 20 + jsonLength;
    if (next + 8 <= length && readU32(bytes, next + 4) == kBinChunk) {
        std::uint64_t binLength = readU32(bytes, next);
        if (next + 8 + binLength > length)
            fail("", "truncated .glb: its BIN chunk of " + std::to_string(binLength) + " bytes runs past the end (" +
                         std::to_string(length) + " bytes)");
        chunks.binOffset = next + 8;
        chunks.binSize = binLength;
    }
    return chunks;
}

void checkNesting(const std::string& text) {
    int depth = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (inString) {
            if (c == '\\') ++i;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '{' || c == '[') {
            if (++depth > kMaxJsonDepth) fail("", "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        } else if (c == '}' || c == ']') {
            --depth;
        }
    }
}

void checkDocument(const Json& root, const std::filesystem::path& file, const GlbChunks* glb, const ReadScope& modelScope) {
    if (!root.is_object()) fail("", "expected a JSON object at the top level");
    auto asset = root.find("asset");
    if (asset == root.end() || !asset->is_object() || !asset->contains("version") || !(*asset)["version"].is_string())
        fail("/asset", "missing \"version\" (a glTF file says \"asset\": {\"version\": \"2.0\"})");
    std::string version = (*asset)["version"].get<std::string>();
    if (version.rfind("2.", 0) != 0) fail("/asset/version", "glTF " + version + " (only 2.x is read)");

    if (auto required = root.find("extensionsRequired"); required != root.end() && required->is_array()) {
        for (std::size_t i = 0; i < required->size(); ++i) {
            const Json& name = (*required)[i];
            if (name.is_string() && !kSupportedExtensions.count(name.get<std::string>()))
                fail(at("extensionsRequired", i), "the file requires " + name.get<std::string>() +
                                                      ", which ptview does not support");
        }
    }

    std::vector<std::uint64_t> bufferLengths;
    if (auto buffers = root.find("buffers"); buffers != root.end() && buffers->is_array()) {
        for (std::size_t i = 0; i < buffers->size(); ++i) {
            const Json& buffer = (*buffers)[i];
            if (!buffer.is_object()) fail(at("buffers", i), "expected an object");
            std::uint64_t byteLength = unsignedOr(buffer, "byteLength", 0, at("buffers", i));
            bufferLengths.push_back(byteLength);
            auto uri = buffer.find("uri");
            if (uri == buffer.end() || !uri->is_string()) {
                if (!glb) fail(at("buffers", i), "no \"uri\" (only a .glb's first buffer may leave it out)");
                if (i != 0) fail(at("buffers", i), "no \"uri\" (only the first buffer may be the .glb's BIN chunk)");
                if (glb->binSize < byteLength)
                    fail(at("buffers", i) + "/byteLength",
                         std::to_string(byteLength) + " bytes, but the .glb's BIN chunk holds " + std::to_string(glb->binSize));
                continue;
            }
            std::string text = uri->get<std::string>();
            if (isDataUri(text)) {
                std::uint64_t held = dataUriBytes(text);
                if (held < byteLength)
                    fail(at("buffers", i) + "/byteLength",
                         std::to_string(byteLength) + " bytes, but its data URI holds " + std::to_string(held));
                continue;
            }
            std::filesystem::path resource = resourcePath(file, text, modelScope, at("buffers", i) + "/uri");
            checkResourceFile(resource, at("buffers", i) + "/uri", "glTF buffer");
            std::error_code error;
            std::uintmax_t size = std::filesystem::file_size(resource, error);
            if (!error && size < byteLength)
                fail(at("buffers", i) + "/byteLength",
                     std::to_string(byteLength) + " bytes, but " + resource.string() + " holds only " + std::to_string(size));
        }
    }

    if (auto views = root.find("bufferViews"); views != root.end() && views->is_array()) {
        for (std::size_t i = 0; i < views->size(); ++i) {
            const Json& view = (*views)[i];
            if (!view.is_object()) fail(at("bufferViews", i), "expected an object");
            std::uint64_t buffer = unsignedOr(view, "buffer", UINT64_MAX, at("bufferViews", i));
            if (buffer >= bufferLengths.size()) fail(at("bufferViews", i) + "/buffer", "names no buffer");
            std::uint64_t offset = unsignedOr(view, "byteOffset", 0, at("bufferViews", i));
            std::uint64_t length = unsignedOr(view, "byteLength", 0, at("bufferViews", i));
            if (offset > bufferLengths[buffer] || length > bufferLengths[buffer] - offset)
                fail(at("bufferViews", i), "bytes " + std::to_string(offset) + " to " + std::to_string(offset + length) +
                                               " run past the end of buffer " + std::to_string(buffer) + " (" +
                                               std::to_string(bufferLengths[buffer]) + " bytes)");
        }
    }

    if (auto images = root.find("images"); images != root.end() && images->is_array()) {
        for (std::size_t i = 0; i < images->size(); ++i) {
            const Json& image = (*images)[i];
            if (!image.is_object()) fail(at("images", i), "expected an object");
            auto uri = image.find("uri");
            if (uri != image.end() && uri->is_string() && !isDataUri(uri->get<std::string>()))
                checkResourceFile(resourcePath(file, uri->get<std::string>(), modelScope, at("images", i) + "/uri"),
                                  at("images", i) + "/uri", "glTF image");
        }
    }

    // Before tinygltf copies them: a count is checked before anything is sized by it.
    if (auto accessors = root.find("accessors"); accessors != root.end() && accessors->is_array()) {
        for (std::size_t i = 0; i < accessors->size(); ++i) {
            const Json& accessor = (*accessors)[i];
            if (!accessor.is_object()) fail(at("accessors", i), "expected an object");
            std::uint64_t count = unsignedOr(accessor, "count", 0, at("accessors", i));
            if (count > kMaxAccessorElements)
                fail(at("accessors", i) + "/count", std::to_string(count) + " elements, more than the " +
                                                        std::to_string(kMaxAccessorElements) +
                                                        " an accessor may hold (docs/scene-format.md, \"Limits\")");
        }
    }
}

} // namespace ptview::gltf
