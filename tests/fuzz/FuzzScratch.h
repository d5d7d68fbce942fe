#pragma once
// The loaders the fuzz targets drive read files, not bytes: each target writes its input into a
// scratch directory of its own before loading it.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include <unistd.h>

namespace ptview::fuzz {

namespace detail {
inline std::filesystem::path& scratchDirectory() {
    static std::filesystem::path directory;
    return directory;
}
} // namespace detail

// `ptview-fuzz-NAME-PID` in the temporary directory, created empty. It is removed at exit and
// left behind after a crash, with the input that caused it. Called once, from LLVMFuzzerInitialize.
inline std::filesystem::path makeScratchDirectory(const std::string& name) {
    std::filesystem::path& directory = detail::scratchDirectory();
    directory = std::filesystem::temp_directory_path() / ("ptview-fuzz-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::create_directories(directory);
    std::atexit([] {
        std::error_code ignored;
        std::filesystem::remove_all(detail::scratchDirectory(), ignored);
    });
    return directory;
}

// Writes bytes to path, replacing what was there; a target that cannot write its input would
// test nothing, so that stops the run.
inline void writeInput(const std::filesystem::path& path, std::string_view bytes) {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!file) {
        std::fprintf(stderr, "fuzz: cannot write %s\n", path.c_str());
        std::abort();
    }
}

} // namespace ptview::fuzz
