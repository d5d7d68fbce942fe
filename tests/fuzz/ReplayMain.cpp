// A main for the fuzz targets without libFuzzer: LLVMFuzzerInitialize (where a target has one),
// then LLVMFuzzerTestOneInput on each file named, as libFuzzer does when it is handed files. A
// target's oracle aborts on a finding, so the process fails the test that runs it.
//
// Why: the fuzzers run only in the hardening job (.ci/hardening), so a target whose own checks
// fell behind the code (a script command its table lacks) went unnoticed there. Built by the main
// build and run by CTest over the shipped files and the fuzzers' past findings, every target's
// start-up checks and oracles run with the rest of the suite.
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

int main(int argc, char** argv) {
    if (LLVMFuzzerInitialize) LLVMFuzzerInitialize(&argc, &argv);
    // No input would make the test pass without running an oracle once.
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s FILE... (at least one input)\n", argv[0]);
        return 2;
    }
    const std::vector<std::filesystem::path> files(argv + 1, argv + argc);
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
