// Small files that once made ptview allocate gigabytes (issue 33, "Files from strangers"): each is
// handed to the real binary, which must refuse it (exit 2) naming the file, the place and the
// limit, within a second of CPU time and under 100 MB of peak memory, measured on the child
// process itself (wait4's rusage).
#include "ClaimingPng.h"
#include "TestFiles.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>
#include <vector>

namespace ptview {
namespace {

using Json = nlohmann::json;
using testing::ScratchFiles;

const std::string kBinary = PTVIEW_BINARY;

constexpr double kMaxCpuSeconds = 1.0;
constexpr long kMaxPeakBytes = 100L << 20;

struct MeasuredRun {
    int exitCode = -1;     // -1: it did not exit (a signal) or could not be run
    double cpuSeconds = 0; // user + system
    long peakBytes = 0;    // the largest resident set it had
    std::string output;    // stdout and stderr
};

// Runs ptview with `arguments`, its output into `log`, and measures it as the kernel counted it.
MeasuredRun runPtview(const std::vector<std::string>& arguments, const std::filesystem::path& log) {
    std::vector<char*> argv{const_cast<char*>(kBinary.c_str())};
    for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
    argv.push_back(nullptr);
    MeasuredRun run;
    std::fflush(nullptr);
    const pid_t child = ::fork();
    if (child < 0) return run;
    if (child == 0) {
        const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd < 0) ::_exit(127);
        ::dup2(fd, 1);
        ::dup2(fd, 2);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    int status = 0;
    rusage usage{};
    if (::wait4(child, &status, 0, &usage) != child) return run;
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.cpuSeconds = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                     1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
    run.peakBytes = usage.ru_maxrss * 1024L; // kilobytes on Linux
    run.output = testing::readFileBytes(log);
    return run;
}

MeasuredRun renderRefused(const ScratchFiles& files, const std::filesystem::path& scene) {
    const auto out = files.write("out.pfm", "");
    std::filesystem::remove(out);
    MeasuredRun run = runPtview({"render", scene.string(), "--out", out.string(), "--spp", "1", "--size", "16x16"},
                                files.write("log.txt", ""));
    EXPECT_FALSE(std::filesystem::exists(out)) << "an image was written";
    return run;
}

void expectRefusedSmallAndFast(const MeasuredRun& run, const std::vector<std::string>& words) {
    EXPECT_EQ(run.exitCode, 2) << run.output;
    for (const std::string& word : words) EXPECT_NE(run.output.find(word), std::string::npos) << word << " in: " << run.output;
    EXPECT_LT(run.cpuSeconds, kMaxCpuSeconds) << run.output;
    EXPECT_LT(run.peakBytes, kMaxPeakBytes) << run.output;
}

// 400 bytes: one accessor without a buffer view, 4e8 VEC3 of zeros (4.8 GB as floats).
TEST(HostileModel, AnAccessorOfFourHundredMillionZerosIsRefusedFastAndSmall) {
    ScratchFiles files("hostile_model");
    Json gltf = {{"asset", {{"version", "2.0"}}},
                 {"accessors", {{{"componentType", 5126}, {"count", 400000000}, {"type", "VEC3"}}}},
                 {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
                 {"nodes", {{{"mesh", 0}}}},
                 {"scenes", {{{"nodes", {0}}}}}};
    const std::string text = gltf.dump();
    ASSERT_LT(text.size(), 400u);
    const auto path = files.write("zeros.gltf", text);
    expectRefusedSmallAndFast(renderRefused(files, path), {path.string() + ": /accessors/0/count: 400000000 elements", "50331648"});
}

// Six PNGs of 100 bytes, each claiming 16384 x 16384 pixels (1 GiB decoded): refused from their
// headers, before one is decoded, whether a scene file or a glTF file names them.
TEST(HostileModel, SixTexturesClaiming16384SquaredAreRefusedFastAndSmall) {
    ScratchFiles files("hostile_textures");
    Json materials = Json::object();
    for (int i = 0; i < 6; ++i) {
        const std::string name = "bomb" + std::to_string(i) + ".png";
        files.write(name, testing::pngClaimingSize(16384, 16384));
        materials["m" + std::to_string(i)] = {{"type", "diffuse"}, {"albedo", {{"texture", name}}}};
    }
    Json scene = {{"camera", {{"eye", {0, 0, 3}}, {"target", {0, 0, 0}}, {"vfov_deg", 40}, {"resolution", {16, 16}}}},
                  {"materials", materials},
                  {"shapes", {{{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}, {"material", "m0"}}}}};
    const auto path = files.write("bombs.json", scene.dump());
    expectRefusedSmallAndFast(renderRefused(files, path),
                              {path.string() + ": /materials/m1/albedo/texture: ", "bomb1.png: a 16384x16384 image takes 1024 MiB",
                               "the limit of 1024 MiB"});
}

TEST(HostileModel, SixGltfImagesClaiming16384SquaredAreRefusedFastAndSmall) {
    ScratchFiles files("hostile_images");
    // One triangle, each of six materials with its own image file.
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::string bin(reinterpret_cast<const char*>(positions), sizeof positions);
    Json gltf = {{"asset", {{"version", "2.0"}}},
                 {"buffers", {{{"uri", "triangle.bin"}, {"byteLength", bin.size()}}}},
                 {"bufferViews", {{{"buffer", 0}, {"byteLength", bin.size()}}}},
                 {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}}},
                 {"nodes", Json::array()}, {"meshes", Json::array()}, {"materials", Json::array()},
                 {"textures", Json::array()}, {"images", Json::array()}};
    files.write("triangle.bin", bin);
    for (int i = 0; i < 6; ++i) {
        const std::string name = "bomb" + std::to_string(i) + ".png";
        files.write(name, testing::pngClaimingSize(16384, 16384));
        gltf["images"].push_back({{"uri", name}});
        gltf["textures"].push_back({{"source", i}});
        gltf["materials"].push_back({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", i}}}}}});
        gltf["meshes"].push_back({{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"material", i}}}}});
        gltf["nodes"].push_back({{"mesh", i}});
    }
    const auto path = files.write("bombs.gltf", gltf.dump());
    expectRefusedSmallAndFast(renderRefused(files, path),
                              {path.string() + ": /images/1: ", "bomb1.png: a 16384x16384 image takes 1024 MiB", "the limit of 1024 MiB"});
}

} // namespace
} // namespace ptview
