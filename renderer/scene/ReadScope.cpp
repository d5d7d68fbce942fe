#include "ReadScope.h"

#include <system_error>

namespace ptview {
namespace {

std::vector<std::filesystem::path> resolvedAll(std::vector<std::filesystem::path> directories) {
    for (std::filesystem::path& directory : directories) directory = resolvedPath(directory);
    return directories;
}

} // namespace

std::filesystem::path resolvedPath(const std::filesystem::path& file) {
    std::error_code error;
    std::filesystem::path absolute = std::filesystem::absolute(file, error);
    if (error) absolute = file;
    std::filesystem::path resolved = std::filesystem::weakly_canonical(absolute, error);
    return error ? absolute.lexically_normal() : resolved;
}

bool isInsideDirectory(const std::filesystem::path& file, const std::filesystem::path& directory) {
    const std::filesystem::path resolvedFile = resolvedPath(file);
    const std::filesystem::path resolvedDirectory = resolvedPath(directory);
    // Component by component: "/a/bc" is not inside "/a/b".
    auto d = resolvedDirectory.begin();
    auto f = resolvedFile.begin();
    for (; d != resolvedDirectory.end(); ++d, ++f) {
        if (d->empty()) continue; // a trailing separator
        if (f == resolvedFile.end() || *f != *d) return false;
    }
    return true;
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
    if (isInsideDirectory(file, *root_)) return std::nullopt;
    for (const std::filesystem::path& allowed : allowed_)
        if (isInsideDirectory(file, allowed)) return std::nullopt;
    const std::filesystem::path resolved = resolvedPath(file);
    refused_->push_back(resolved);
    return resolved.string() + " is outside " + rootRole_ + " " + root_->string() +
           " (files from a scene someone sent are read only there; allow its folder with --allow-dir " +
           resolved.parent_path().string() + ")";
}

} // namespace ptview
