#include <ptview/scene/ReadScope.h>

#include <system_error>

namespace ptview {
namespace {

std::vector<std::filesystem::path> resolvedAll(std::vector<std::filesystem::path> directories) {
    for (std::filesystem::path& directory : directories) directory = resolvedPath(directory);
    return directories;
}

// Whether `file` lies in `directory`'s tree (the directory itself included), both resolved
// (resolvedPath): component by component, so "/a/bc" is not inside "/a/b".
bool liesIn(const std::filesystem::path& file, const std::filesystem::path& directory) {
    auto f = file.begin();
    for (const std::filesystem::path& component : directory) {
        if (f == file.end() || *f != component) return false;
        ++f;
    }
    return true;
}

} // namespace

std::filesystem::path resolvedPath(const std::filesystem::path& file) {
    std::error_code error;
    std::filesystem::path absolute = std::filesystem::absolute(file, error);
    if (error) absolute = file;
    std::filesystem::path resolved = std::filesystem::weakly_canonical(absolute, error);
    return error ? absolute.lexically_normal() : resolved;
}

ReadScope ReadScope::within(const std::filesystem::path& rootDirectory, std::string rootRole,
                            std::vector<std::filesystem::path> allowedDirectories) {
    ReadScope scope;
    scope.root_ = resolvedPath(rootDirectory.empty() ? std::filesystem::path(".") : rootDirectory);
    scope.rootRole_ = std::move(rootRole);
    scope.allowed_ = resolvedAll(std::move(allowedDirectories));
    return scope;
}

ReadScope ReadScope::anywhere(std::vector<std::filesystem::path> allowedDirectories) {
    ReadScope scope;
    scope.allowed_ = resolvedAll(std::move(allowedDirectories));
    return scope;
}

ReadScope ReadScope::forModel(const std::filesystem::path& modelFile) const {
    ReadScope scope;
    scope.root_ = resolvedPath(modelFile).parent_path();
    scope.rootRole_ = "the folder of " + modelFile.filename().string();
    scope.allowed_ = allowed_;
    scope.refused_ = refused_;
    return scope;
}

std::optional<std::string> ReadScope::refusal(const std::filesystem::path& file) const {
    if (!root_) return std::nullopt;
    const std::filesystem::path resolved = resolvedPath(file); // the directories are resolved already
    if (liesIn(resolved, *root_)) return std::nullopt;
    for (const std::filesystem::path& allowed : allowed_)
        if (liesIn(resolved, allowed)) return std::nullopt;
    refused_->push_back(resolved);
    return resolved.string() + " is outside " + rootRole_ + " " + root_->string() +
           " (files from a scene someone sent are read only there; allow its folder with --allow-dir " +
           resolved.parent_path().string() + ")";
}

} // namespace ptview
