#pragma once
// Which files a scene may make ptview read: the trust boundary for files from strangers
// (docs/robustness.md, "Files from strangers").
//
// A scene file the user names reads what it names. A scene carried in an image's metadata (a PNG
// or EXR someone sent) reads only inside the image's own folder tree, and a glTF file's buffers and
// images only inside the model's own folder tree, wherever the model was named from; each may read
// more only in folders the user allowed (`--allow-dir DIR`, the viewer's prompt). Paths are
// compared after symbolic links are resolved, so a link inside the folder to a file outside it is
// outside.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ptview {

class ReadScope {
public:
    // Any file: a scene the user named. Its glTF files are still confined (forModel).
    ReadScope() = default;
    // Only inside `rootDirectory`'s tree (for messages: `rootRole`, e.g. "the image's folder") and
    // the allowed directories.
    static ReadScope within(const std::filesystem::path& rootDirectory, std::string rootRole,
                            std::vector<std::filesystem::path> allowedDirectories);
    // Any file, and the allowed directories for the glTF files it reads.
    static ReadScope anywhere(std::vector<std::filesystem::path> allowedDirectories);

    // The scope of the resources of the glTF file `modelFile` read under this one: the model's own
    // folder and this scope's allowed directories. Refusals are recorded with this scope's.
    ReadScope forModel(const std::filesystem::path& modelFile) const;

    bool confined() const { return root_.has_value(); }
    // nullopt when `file` may be read; else why not, e.g. "/etc/passwd is outside the image's
    // folder /home/me/Downloads (allow its folder with --allow-dir /etc)". Records the refusal.
    std::optional<std::string> refusal(const std::filesystem::path& file) const;
    // The files refused so far by this scope and every scope made from it (forModel), in order:
    // what a prompt offers to allow.
    const std::vector<std::filesystem::path>& refusedFiles() const { return *refused_; }
    const std::vector<std::filesystem::path>& allowedDirectories() const { return allowed_; }

private:
    std::optional<std::filesystem::path> root_; // canonical
    std::string rootRole_;
    std::vector<std::filesystem::path> allowed_; // canonical
    std::shared_ptr<std::vector<std::filesystem::path>> refused_ = std::make_shared<std::vector<std::filesystem::path>>();
};

// `file` with symbolic links and "." / ".." resolved as far as it exists (weakly_canonical),
// absolute. Never throws: a path that cannot be resolved comes back lexically normalized.
std::filesystem::path resolvedPath(const std::filesystem::path& file);

} // namespace ptview
