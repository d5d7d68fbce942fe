#pragma once
// Reading an input file whole, with the checks every loader needs before it trusts a file: it is
// a regular file (not a directory, not /dev/zero, not a FIFO that would block or a device that
// never ends), it is no larger than its format can reasonably be, and the memory for its bytes is
// there. Each loader states its own limit and rethrows the error as its own kind.

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace ptview {

// what() reads "FILE: reason", on one line.
class InputFileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

constexpr std::uintmax_t kMiB = std::uintmax_t(1) << 20;

// The whole file. `kind` names it in messages ("scene file", "MTL file"). Throws InputFileError:
// "FILE: cannot open KIND: REASON" when it cannot be opened or is not a regular file,
// "FILE: KIND too large (N MiB; at most M MiB)" and "FILE: not enough memory to load it (N MiB on disk)"
// (the words the loaders use when the memory runs out later, while they parse).
std::string readInputFile(const std::filesystem::path& path, std::uintmax_t maxBytes, const char* kind);

// The same checks without reading: throws InputFileError unless `path` names a regular file that
// can be opened for reading (for readers that stream, such as the PFM reader).
void checkInputFile(const std::filesystem::path& path, const char* kind);

// readInputFile, rethrowing as the loader's own error type.
template <class Error>
std::string readInputFileAs(const std::filesystem::path& path, std::uintmax_t maxBytes, const char* kind) {
    try {
        return readInputFile(path, maxBytes, kind);
    } catch (const InputFileError& e) {
        throw Error(e.what());
    }
}

} // namespace ptview
