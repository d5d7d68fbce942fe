#include <ptview/commands/OutputPath.h>

#include <ptview/io/ImageIO.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <iostream>
#include <system_error>
#include <fcntl.h>
#include <unistd.h>

namespace ptview {
namespace {

namespace fs = std::filesystem;

// Creates and removes a file beside where the writer will put its temporary, with a name of the
// same length: whatever would refuse the write (permissions, a read-only file system, a name
// longer than the file system takes, a path component that is a file) refuses this. Returns the
// reason, or nullopt.
std::optional<std::string> cannotCreateIn(const fs::path& target) {
    const fs::path probe = temporaryPathFor(target);
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) {
        if (errno == EEXIST) return std::nullopt; // a leftover of ours: creating is possible there
        return std::string(std::strerror(errno));
    }
    ::close(fd);
    ::unlink(probe.c_str());
    return std::nullopt;
}

} // namespace

std::optional<std::string> outputPathProblem(const std::string& path, std::initializer_list<const char*> allowed) {
    const fs::path out(path);
    std::string extension = out.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (std::none_of(allowed.begin(), allowed.end(), [&](const char* e) { return extension == e; })) {
        std::string list;
        for (const char* e : allowed) list += (list.empty() ? "" : " or ") + std::string(e);
        return path + ": unsupported output format (use " + list + ")";
    }
    fs::path target;
    try {
        target = writeTarget(out);
    } catch (const std::exception& e) {
        return std::string(e.what());
    }
    std::error_code error;
    const fs::file_status existing = fs::status(target, error);
    if (fs::is_directory(existing)) return path + ": is a directory";
    // Renaming over a device or a FIFO would replace it (as root, /dev/null) instead of writing to it.
    if (fs::exists(existing) && !fs::is_regular_file(existing)) return path + ": exists and is not a regular file";
    const fs::path directory = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    const fs::file_status status = fs::status(directory, error);
    if (status.type() == fs::file_type::not_found) return path + ": directory " + directory.string() + " does not exist";
    if (!error && !fs::is_directory(status)) return path + ": " + directory.string() + " is not a directory";
    if (std::optional<std::string> why = cannotCreateIn(target)) return path + ": cannot write here: " + *why;
    return std::nullopt;
}

std::optional<std::string> checkOutputPath(const std::string& path, std::initializer_list<const char*> allowed) {
    if (std::optional<std::string> problem = outputPathProblem(path, allowed)) {
        std::cerr << "ptview: " << *problem << "\n";
        return std::nullopt;
    }
    std::string extension = fs::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

std::optional<std::string> outputDirectoryProblem(const fs::path& directory) {
    std::error_code error;
    const fs::file_status status = fs::status(directory, error);
    if (status.type() != fs::file_type::not_found && !error && !fs::is_directory(status))
        return directory.string() + ": exists and is not a directory";
    if (status.type() == fs::file_type::not_found) {
        fs::create_directories(directory, error);
        if (error) return directory.string() + ": cannot create the directory: " + error.message();
    }
    if (std::optional<std::string> why = cannotCreateIn(directory / "summary.md"))
        return directory.string() + ": cannot write here: " + *why;
    return std::nullopt;
}

} // namespace ptview
