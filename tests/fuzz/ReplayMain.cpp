// A main for the fuzz targets without libFuzzer: LLVMFuzzerInitialize (where a target has one),
// then LLVMFuzzerTestOneInput on every file named and every file below every folder named, as
// libFuzzer does when it is handed files. A target's oracle aborts on a finding, so the process
// fails the test that runs it.
//
// Why: the fuzzers run only in the hardening job (.ci/hardening), so a target whose own checks
// fell behind the code (a script command its table lacks) went unnoticed there. Built by the main
// build and run by CTest over the shipped files and the fuzzers' past findings, every target's
// start-up checks and oracles run with the rest of the suite.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
extern "C" __attribute__((weak)) int LLVMFuzzerInitialize(int* argc, char*** argv);

namespace {

std::vector<std::filesystem::path> inputFiles(int argc, char** argv) {
    std::vector<std::filesystem::path> files;
    for (int i = 1; i < argc; ++i) {
        const std::filesystem::path named = argv[i];
        if (std::filesystem::is_directory(named)) {
            for (const auto& entry : std::filesystem::recursive_directory_iterator(named))
                if (entry.is_regular_file()) files.push_back(entry.path());
        } else if (std::filesystem::is_regular_file(named)) {
            files.push_back(named);
        } else {
            std::fprintf(stderr, "%s: no such file or folder\n", named.c_str());
            files.clear();
            return files;
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

} // namespace

int main(int argc, char** argv) {
    if (LLVMFuzzerInitialize) LLVMFuzzerInitialize(&argc, &argv);
    const std::vector<std::filesystem::path> files = inputFiles(argc, argv);
    // No input would make the test pass without running an oracle once.
    if (files.empty()) {
        std::fprintf(stderr, "usage: %s FILE_OR_FOLDER... (at least one input)\n", argv[0]);
        return 2;
    }
    for (const std::filesystem::path& file : files) {
        std::ifstream stream(file, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
        if (!stream.good() && !stream.eof()) {
            std::fprintf(stderr, "%s: cannot read\n", file.c_str());
            return 2;
        }
        LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    }
    std::printf("replayed %zu inputs\n", files.size());
    return 0;
}
