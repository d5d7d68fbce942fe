#pragma once
// Checks an output path before any work is done, so that a typo, a missing or read-only
// directory or a name too long costs nothing: what can be known before the write is refused up
// front (exit 2, naming the path); only what the write itself meets (a full disk) fails later.

#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>

namespace ptview {

// Why `path` cannot be written as one of the `allowed` extensions (e.g. ".png", compared ignoring
// case), as "PATH: reason"; nullopt when it can as far as can be told without writing it. The
// checks: the extension; the target (through a symbolic link, the file it names) is a regular
// file if it exists (not a directory, a device or a FIFO); its directory exists; a file can be created there under the writer's temporary name
// (write permission, a read-only file system, a name too long).
std::optional<std::string> outputPathProblem(const std::string& path, std::initializer_list<const char*> allowed);

// The path's lower-case extension, or nullopt after printing outputPathProblem on stderr
// ("ptview: PATH: ...").
std::optional<std::string> checkOutputPath(const std::string& path, std::initializer_list<const char*> allowed);

// For an output directory (`converge -o DIR`): creates it when missing and checks that files can
// be created in it. Why not, as "DIR: reason", or nullopt.
std::optional<std::string> outputDirectoryProblem(const std::filesystem::path& directory);

} // namespace ptview
