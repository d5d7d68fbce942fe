#include <ptview/scene/GltfFileCallbacks.h>

#include <ptview/scene/GltfDocumentCheck.h>
#include <ptview/io/InputFile.h>

#include <tiny_gltf.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <system_error>

namespace ptview::gltf {
namespace {

// tinygltf looks for a resource beside the model and then in the working directory, and joins
// the URI as it is; checkDocument refused every URI outside the model's scope already, and the
// callbacks refuse again whatever path tinygltf comes up with (user data: the model's ReadScope).
bool fileExists(const std::string& path, void* user) {
    const std::filesystem::path file = std::filesystem::u8path(path);
    if (static_cast<const ReadScope*>(user)->refusal(file)) return false;
    std::error_code error;
    return std::filesystem::is_regular_file(file, error);
}

std::string expandFilePath(const std::string& path, void*) {
    return path; // no ~ or $VAR expansion: a file names its resources literally
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    if (std::optional<std::string> refusal = static_cast<const ReadScope*>(user)->refusal(std::filesystem::u8path(path))) {
        if (err) *err = *refusal;
        return false;
    }
    try {
        std::string bytes = readInputFile(std::filesystem::u8path(path), kMaxResourceBytes, "glTF resource");
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const InputFileError& e) {
        if (err) *err = e.what();
        return false;
    }
}

bool writeWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err = "ptview does not write glTF files";
    return false;
}

bool keepImageBytes(tinygltf::Image*, const int index, std::string*, std::string*, int, int, const unsigned char* bytes,
                    int size, void* user) {
    auto& context = *static_cast<LoadContext*>(user);
    if (index < 0 || size < 0) return false;
    if (context.encodedImages.size() <= static_cast<std::size_t>(index))
        context.encodedImages.resize(static_cast<std::size_t>(index) + 1);
    context.encodedImages[static_cast<std::size_t>(index)].assign(bytes, bytes + size);
    return true;
}

} // namespace

void useCallbacks(tinygltf::TinyGLTF& parser, const ReadScope& scope, LoadContext& context) {
    parser.SetFsCallbacks(tinygltf::FsCallbacks{&fileExists, &expandFilePath, &readWholeFile, &writeWholeFile,
                                                const_cast<ReadScope*>(&scope)});
    parser.SetImageLoader(&keepImageBytes, &context);
}

std::string tinygltfReason(const std::string& err) {
    std::string out;
    std::size_t start = 0;
    while (start < err.size()) {
        std::size_t end = err.find('\n', start);
        if (end == std::string::npos) end = err.size();
        std::string line = err.substr(start, std::min<std::size_t>(end - start, 160));
        if (!line.empty()) out += (out.empty() ? "" : "; ") + line;
        start = end + 1;
    }
    return "tinygltf: " + (out.empty() ? std::string("cannot parse the file") : out);
}

} // namespace ptview::gltf
