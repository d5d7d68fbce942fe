#include <ptview/model/NearbyFiles.h>

#include <algorithm>
#include <set>
#include <system_error>

namespace ptview {
namespace {

void appendFilesWithExtension(const std::filesystem::path& folder, const std::string& extension,
                              std::set<std::filesystem::path>& seen, std::vector<std::filesystem::path>& files) {
    std::error_code error;
    for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
        std::error_code typeError;
        if (!it->is_regular_file(typeError) || it->path().extension() != extension) continue;
        // The same file reached through two of the folders (a symlink, "x/../x") is offered once.
        std::error_code canonicalError;
        const std::filesystem::path canonical = std::filesystem::weakly_canonical(it->path(), canonicalError);
        if (seen.insert(canonicalError ? it->path() : canonical).second) files.push_back(it->path().lexically_normal());
    }
}

} // namespace

std::vector<std::filesystem::path> filesWithExtension(const std::filesystem::path& folder, const std::string& extension) {
    std::set<std::filesystem::path> seen;
    std::vector<std::filesystem::path> files;
    appendFilesWithExtension(folder, extension, seen, files);
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<std::filesystem::path> environmentMapsNear(const std::filesystem::path& scenePath,
                                                       const std::filesystem::path& fallbackFolder) {
    std::vector<std::filesystem::path> folders;
    if (scenePath.empty()) {
        folders = {fallbackFolder};
    } else {
        const std::filesystem::path folder = scenePath.parent_path().empty() ? "." : scenePath.parent_path();
        folders = {folder, folder / "hdr", folder / ".." / "hdr"};
    }
    std::set<std::filesystem::path> seen;
    std::vector<std::filesystem::path> files;
    for (const std::filesystem::path& folder : folders) appendFilesWithExtension(folder, ".hdr", seen, files);
    std::sort(files.begin(), files.end());
    return files;
}

std::filesystem::path nameRelativeToScene(const std::filesystem::path& file, const std::filesystem::path& scenePath) {
    if (scenePath.empty()) return file;
    std::error_code error;
    const std::filesystem::path base = std::filesystem::absolute(scenePath.parent_path(), error);
    const std::filesystem::path target = std::filesystem::absolute(file, error);
    if (error || base.root_path() != target.root_path()) return file;
    const std::filesystem::path relative = target.lexically_normal().lexically_relative(base.lexically_normal());
    return relative.empty() ? file : relative;
}

} // namespace ptview
