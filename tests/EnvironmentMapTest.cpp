// Environment maps: reading .hdr files (and refusing bad ones by name), the scene format's
// "environment" keys, and, on the GPU through tests/shaders/environment_probe.frag, the real
// shaders/environment_map.glsl: the documented orientation, samples that follow the density
// (chi-square on the very bright small sun of rooitou_park and on synthetic maps), a density that
// integrates to one and agrees with the sampler, and renders that give the closed-form answers.
#include "ChiSquare.h"
#include <ptview/scene/EnvironmentMap.h>
#include "GlTestContext.h"
#include "LimitedChild.h"
#include <ptview/gpu/GpuEnvironmentMap.h>
#include <ptview/tracer/PathTracer.h>
#include <ptview/probes/ProbePass.h>
#include "RunCommand.h"
#include <ptview/scene/Scene.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/scene/SceneWriter.h>
#include <ptview/gl/ShaderAssembler.h>

#include <stb_image.h>
#include <stb_image_write.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

namespace ptview {
namespace {

namespace fs = std::filesystem;
using testing::ChiSquareResult;

constexpr double kPi = 3.14159265358979323846;
constexpr double kSignificance = 0.01; // for the whole file, Sidak-corrected per chi-square test
constexpr int kChiSquareTests = 4;
constexpr int kEnvironmentUnit = 13;   // as in PathTracer: units 13..15
const std::string kRooitou = PTVIEW_ASSETS_DIR "/hdr/rooitou_park_1k.hdr";
const std::string kStudio = PTVIEW_ASSETS_DIR "/hdr/studio_small_03_1k.hdr";

// ---- The documented orientation (docs/scene-format.md), written out independently of the shader

glm::dvec3 rotateY(glm::dvec3 d, double degrees) {
    double a = degrees * kPi / 180.0;
    return {d.x * std::cos(a) + d.z * std::sin(a), d.y, -d.x * std::sin(a) + d.z * std::cos(a)};
}

// d(u, v) = (-sin phi sin theta, cos theta, cos phi sin theta), theta = pi v, phi = 2 pi u, then
// turned about +Y by rotation_deg (right-hand rule).
glm::dvec3 documentedDirection(double u, double v, double rotationDeg) {
    double theta = kPi * v, phi = 2.0 * kPi * u;
    return rotateY({-std::sin(phi) * std::sin(theta), std::cos(theta), std::cos(phi) * std::sin(theta)}, rotationDeg);
}

glm::dvec2 documentedUv(glm::dvec3 d, double rotationDeg) {
    glm::dvec3 m = rotateY(d, -rotationDeg);
    double phi = std::atan2(-m.x, m.z);
    if (phi < 0.0) phi += 2.0 * kPi;
    return {phi / (2.0 * kPi), std::atan2(std::hypot(m.x, m.z), m.y) / kPi};
}

glm::dvec3 texelCentreDirection(const EnvironmentMap& map, int i, int j, double rotationDeg) {
    return documentedDirection((i + 0.5) / map.width, (j + 0.5) / map.height, rotationDeg);
}

glm::vec3 texelRadiance(const EnvironmentMap& map, int i, int j) {
    const float* p = &map.rgb[(std::size_t(j) * std::size_t(map.width) + std::size_t(i)) * 3];
    return {p[0], p[1], p[2]};
}

// ---- Maps

// Random radiance spanning six orders of magnitude, a fifth of the texels black, one very bright
// texel and bright texels in the rows next to the poles.
EnvironmentMap syntheticMap(int width, int height, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> logValue(0.0f, 2.0f);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<float> rgb(std::size_t(width) * std::size_t(height) * 3);
    for (std::size_t t = 0; t < rgb.size() / 3; ++t) {
        float scale = unit(rng) < 0.2f ? 0.0f : std::exp(logValue(rng));
        for (int c = 0; c < 3; ++c) rgb[t * 3 + c] = scale * (0.5f + unit(rng));
    }
    auto set = [&](int i, int j, float value) {
        for (int c = 0; c < 3; ++c) rgb[(std::size_t(j) * std::size_t(width) + std::size_t(i)) * 3 + c] = value;
    };
    set(width / 3, height / 2, 2e4f);
    set(1, 0, 50.0f);
    set(width - 2, height - 1, 50.0f);
    return makeEnvironmentMap(width, height, std::move(rgb), "synthetic");
}

const EnvironmentMap& rooitou() {
    static const EnvironmentMap map = loadEnvironmentMap(kRooitou);
    return map;
}

std::vector<glm::vec2> uniformPoints(int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::vector<glm::vec2> points(static_cast<std::size_t>(count));
    for (glm::vec2& p : points) {
        p.x = float(rng() >> 8) * 0x1p-24f; // [0, 1) in float
        p.y = float(rng() >> 8) * 0x1p-24f;
    }
    return points;
}

// ---- The GPU probe

struct ProbeSample {
    glm::vec3 direction;
    float pdf = 0.0f;     // what sampleEnvironmentMap reports
    glm::vec2 uv;         // the map coordinates it drew
    float pdfEval = 0.0f; // environmentMapPdf(direction)
    float pdfUv = 0.0f;   // the density in (u, v) of the texel it drew
    glm::vec3 radiance;   // environmentMapRadiance(direction)

    // The solid-angle density of the drawn texel at the drawn point.
    double drawnPdf() const { return pdfUv / (2.0 * kPi * kPi * std::sin(kPi * double(uv.y))); }
};

struct ProbeEvaluation {
    float pdf = 0.0f;
    glm::vec2 uv;
    glm::vec3 radiance;
};

class EnvironmentProbe {
public:
    EnvironmentProbe() {
        testing::glContext();
        ShaderAssembler assembler(PTVIEW_SHADER_DIR);
        program_ = std::make_unique<GlProgram>(assembler.assemble("fullscreen.vert"),
                                               assembler.assemble(PTVIEW_TEST_SHADER_DIR "/environment_probe.frag"));
        program_->bindSamplerUnit("uItems", 0);
        map_.attach(*program_, kEnvironmentUnit);
    }

    void setMap(const EnvironmentMap& map, float intensity = 1.0f, float rotationDeg = 0.0f) {
        map_.upload(&map, intensity, rotationDeg);
    }

    std::vector<ProbeSample> sample(const std::vector<glm::vec2>& u) {
        std::vector<ProbeSample> samples;
        for (std::size_t first = 0; first < u.size(); first += kBatch) {
            ProbeData items;
            for (std::size_t k = first; k < std::min(u.size(), first + kBatch); ++k) items.emplace_back(u[k], 0.0f, 0.0f);
            std::vector<ProbeData> out = run(0, items);
            for (std::size_t k = 0; k < items.size(); ++k)
                samples.push_back({glm::vec3(out[0][k]), out[0][k].w, glm::vec2(out[1][k]), out[1][k].z, out[1][k].w,
                                   glm::vec3(out[2][k])});
        }
        return samples;
    }

    std::vector<ProbeEvaluation> evaluate(const std::vector<glm::vec3>& directions) {
        std::vector<ProbeEvaluation> evaluations;
        for (std::size_t first = 0; first < directions.size(); first += kBatch) {
            ProbeData items;
            for (std::size_t k = first; k < std::min(directions.size(), first + kBatch); ++k)
                items.emplace_back(directions[k], 0.0f);
            std::vector<ProbeData> out = run(1, items);
            for (std::size_t k = 0; k < items.size(); ++k)
                evaluations.push_back({out[0][k].x, glm::vec2(out[0][k].y, out[0][k].z), glm::vec3(out[1][k])});
        }
        return evaluations;
    }

private:
    static constexpr std::size_t kBatch = 1 << 19;

    std::vector<ProbeData> run(int mode, const ProbeData& items) {
        glUseProgram(program_->id());
        glUniform1i(program_->uniformLocation("uProbeMode"), mode);
        map_.bind();
        return runProbePass(*program_, int(items.size()), {items}, 3);
    }

    std::unique_ptr<GlProgram> program_;
    GpuEnvironmentMap map_;
};

EnvironmentProbe& probe() {
    static EnvironmentProbe instance;
    return instance;
}

// Probability of each texel as the GPU density says: pdf at the texel's centre times the texel's
// solid angle in the (u, v) chart, 2 pi^2 sin(theta) du dv. The density times sin(theta) is
// constant over a texel, so this is exact, and the centre is far from any texel edge.
std::vector<double> texelProbabilities(const EnvironmentMap& map, double rotationDeg) {
    std::vector<glm::vec3> centres;
    for (int j = 0; j < map.height; ++j)
        for (int i = 0; i < map.width; ++i) centres.push_back(glm::vec3(texelCentreDirection(map, i, j, rotationDeg)));
    std::vector<ProbeEvaluation> pdf = probe().evaluate(centres);
    std::vector<double> probability(pdf.size());
    const double du = 1.0 / map.width, dv = 1.0 / map.height;
    for (int j = 0; j < map.height; ++j) {
        double jacobian = 2.0 * kPi * kPi * std::sin(kPi * (j + 0.5) * dv) * du * dv;
        for (int i = 0; i < map.width; ++i) {
            std::size_t t = std::size_t(j) * std::size_t(map.width) + std::size_t(i);
            probability[t] = double(pdf[t].pdf) * jacobian;
        }
    }
    return probability;
}

glm::ivec2 texelOf(const EnvironmentMap& map, glm::dvec2 uv) {
    return {std::min(int(uv.x * map.width), map.width - 1), std::min(int(uv.y * map.height), map.height - 1)};
}

void expectChiSquareFit(const std::vector<double>& observed, const std::vector<double>& expected,
                        const std::string& label, const std::function<std::string(std::size_t)>& binLabel) {
    ChiSquareResult result = testing::chiSquareTest(observed, expected);
    const double significance = testing::sidakSignificance(kSignificance, kChiSquareTests);
    std::printf("  %-44s %s\n", label.c_str(), testing::describe(result).c_str());
    EXPECT_GT(result.pValue, significance) << label << ": " << testing::describe(result) << "\n"
                                           << testing::worstBinsTable(observed, expected, binLabel);
}

// Directions binned by their documented map coordinates on a bins.x x bins.y grid of (u, v), whose
// lines include every texel edge (coarser bins are blocks of texels, finer ones cut texels into
// equal parts, which sees where within a texel samples land), against the GPU density integrated
// over each bin: over cells that lie within both one bin and one texel, where the density times
// sin(theta) is constant, its value at the cell's centre times the cell's (u, v) area times
// 2 pi^2 sin(theta) is exact.
void chiSquareOverDirections(const EnvironmentMap& map, double rotationDeg, glm::ivec2 bins, int sampleCount,
                             std::uint32_t seed, const std::string& label) {
    probe().setMap(map, 1.0f, float(rotationDeg));
    const glm::ivec2 cells(std::max(bins.x, map.width), std::max(bins.y, map.height));
    ASSERT_TRUE(cells.x % bins.x == 0 && cells.x % map.width == 0 && cells.y % bins.y == 0 && cells.y % map.height == 0);
    std::vector<glm::vec3> centres;
    for (int j = 0; j < cells.y; ++j)
        for (int i = 0; i < cells.x; ++i)
            centres.push_back(glm::vec3(documentedDirection((i + 0.5) / cells.x, (j + 0.5) / cells.y, rotationDeg)));
    std::vector<ProbeEvaluation> density = probe().evaluate(centres);
    std::vector<double> expected(std::size_t(bins.x * bins.y), 0.0), observed(expected.size(), 0.0);
    auto binOf = [&](glm::dvec2 uv) {
        int x = std::min(int(uv.x * bins.x), bins.x - 1), y = std::min(int(uv.y * bins.y), bins.y - 1);
        return std::size_t(y * bins.x + x);
    };
    for (int j = 0; j < cells.y; ++j) {
        double cellProbabilityPerPdf = 2.0 * kPi * kPi * std::sin(kPi * (j + 0.5) / cells.y) / (double(cells.x) * cells.y);
        for (int i = 0; i < cells.x; ++i)
            expected[binOf({(i + 0.5) / cells.x, (j + 0.5) / cells.y})] +=
                double(density[std::size_t(j) * std::size_t(cells.x) + std::size_t(i)].pdf) * cellProbabilityPerPdf * sampleCount;
    }
    int failed = 0;
    for (const ProbeSample& s : probe().sample(uniformPoints(sampleCount, seed))) {
        failed += s.pdf > 0.0f ? 0 : 1;
        observed[binOf(documentedUv(glm::dvec3(s.direction), rotationDeg))] += 1.0;
    }
    // Only directions rounded across a texel edge into a black texel fail.
    EXPECT_LE(failed, sampleCount / 10000) << "samples with pdf 0";
    expectChiSquareFit(observed, expected, label, [&](std::size_t bin) {
        return "u bin " + std::to_string(bin % bins.x) + ", v bin " + std::to_string(bin / bins.x);
    });
}

// ---- Reading files

class EnvironmentMapFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("ptview_env_" + std::to_string(::getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& bytes) {
        std::ofstream(dir_ / name, std::ios::binary) << bytes;
        return (dir_ / name).string();
    }
    std::string writeHdr(const std::string& name, int width, int height, const std::vector<float>& rgb) {
        std::string path = (dir_ / name).string();
        EXPECT_TRUE(stbi_write_hdr(path.c_str(), width, height, 3, rgb.data()));
        return path;
    }
    static std::string fileBytes(const std::string& path) {
        std::ifstream in(path, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    // The message of loading path, which must fail; it must name the file and be one line.
    static std::string loadError(const std::string& path) {
        try {
            loadEnvironmentMap(path);
        } catch (const EnvironmentMapError& error) {
            std::string message = error.what();
            EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
            return message;
        }
        ADD_FAILURE() << path << " loaded";
        return {};
    }

    fs::path dir_;
};

TEST_F(EnvironmentMapFiles, ReadsTheShippedMapTopRowFirst) {
    const EnvironmentMap& map = rooitou();
    ASSERT_EQ(map.width, 1024);
    ASSERT_EQ(map.height, 512);
    // The sun, as assets/hdr/CREDITS.md measured it: pixel (614, 226), luminance 64,889.8.
    glm::vec3 sun = texelRadiance(map, 614, 226);
    EXPECT_NEAR(0.2126 * sun.r + 0.7152 * sun.g + 0.0722 * sun.b, 64889.8, 0.1);
    EXPECT_EQ(map.marginalCdf.size(), 512u);
    EXPECT_EQ(map.conditionalCdf.size(), 1024u * 512u);
    EXPECT_EQ(map.marginalCdf.back(), 1.0f);
    EXPECT_TRUE(std::is_sorted(map.marginalCdf.begin(), map.marginalCdf.end()));
    for (int j = 0; j < map.height; ++j) {
        auto row = map.conditionalCdf.begin() + std::ptrdiff_t(j) * map.width;
        ASSERT_TRUE(std::is_sorted(row, row + map.width)) << "row " << j;
        ASSERT_EQ(*(row + map.width - 1), 1.0f) << "row " << j;
    }
    // Texels are drawn in proportion to luminance x sin(theta of the row's centre): the sun's
    // probability read from the CDFs matches its share of that weight.
    auto weight = [&](int i, int j) {
        glm::vec3 c = texelRadiance(map, i, j);
        return (0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b) * std::sin(kPi * (j + 0.5) / map.height);
    };
    double total = 0.0;
    for (int j = 0; j < map.height; ++j)
        for (int i = 0; i < map.width; ++i) total += weight(i, j);
    auto cdfStep = [](const std::vector<float>& cdf, std::size_t at, bool first) {
        return double(cdf[at]) - (first ? 0.0 : double(cdf[at - 1]));
    };
    double sunProbability = cdfStep(map.marginalCdf, 226, false) * cdfStep(map.conditionalCdf, 226 * 1024 + 614, false);
    std::printf("  the sun texel (614, 226) is drawn with probability %.4f\n", sunProbability);
    EXPECT_NEAR(sunProbability, weight(614, 226) / total, 1e-5 * sunProbability);
}

TEST_F(EnvironmentMapFiles, WritesAndReadsBackSmallMapsExactly) {
    // Powers of two survive RGBE exactly: a 3x2 map with one value per texel.
    std::vector<float> rgb;
    for (int t = 0; t < 6; ++t) rgb.insert(rgb.end(), {float(1 << t), 0.5f, 0.25f * float(t)});
    EnvironmentMap map = loadEnvironmentMap(writeHdr("small.hdr", 3, 2, rgb));
    EXPECT_EQ(map.rgb, rgb);
    // Mean radiance weights rows by solid angle: both rows of a 2-row map cover half the sphere.
    EXPECT_NEAR(map.meanRadiance.y, 0.5, 1e-12);
    EXPECT_NEAR(map.meanRadiance.x, (1 + 2 + 4 + 8 + 16 + 32) / 6.0, 1e-9);
}

TEST_F(EnvironmentMapFiles, RefusesBadFilesNamingThem) {
    EXPECT_NE(loadError((dir_ / "absent.hdr").string()).find(": cannot open environment map: No such file or directory"),
              std::string::npos);
    EXPECT_NE(loadError(dir_.string()).find(": cannot open environment map: Is a directory"), std::string::npos);
    EXPECT_NE(loadError(write("text.hdr", "not an image\n")).find("not a Radiance .hdr image"), std::string::npos);
    EXPECT_NE(loadError(write("xyze.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 2 +X 4\n")).find("unsupported pixel format"),
              std::string::npos);
    EXPECT_NE(loadError(write("layout.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n+Y 2 +X 4\n")).find("unsupported resolution"),
              std::string::npos);
    EXPECT_NE(loadError(write("huge.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 20000 +X 40000\n")).find("larger than 16384"),
              std::string::npos);
    // stb_image would decode these as black, or (a zero-length run, or the end of the file inside
    // an RLE scanline) never return.
    EXPECT_NE(loadError(write("flat.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n\x80\x80\x80\x81")).find("truncated"),
              std::string::npos);
    std::string rooitouBytes = fileBytes(kRooitou);
    EXPECT_NE(loadError(write("cut.hdr", rooitouBytes.substr(0, 50000))).find("truncated (the file ends inside scanline"),
              std::string::npos);
    std::string zeroRun = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 8\n";
    zeroRun += std::string("\x02\x02\x00\x08", 4) + std::string(1, '\0');
    EXPECT_NE(loadError(write("zero_run.hdr", zeroRun)).find("corrupt run-length data in scanline 0"), std::string::npos);
}

// A Radiance file of one RGBE value everywhere, run-length coded as stb_image_write would, built
// without holding the image: 16384 x 16384 takes 17 MiB.
std::string constantRleHdr(int width, int height, const unsigned char rgbe[4]) {
    std::string bytes = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(height) + " +X " +
                        std::to_string(width) + "\n";
    std::string scanline = {2, 2, char(width >> 8), char(width & 0xFF)};
    for (int channel = 0; channel < 4; ++channel)
        for (int left = width; left > 0; left -= std::min(left, 127))
            scanline += {char(128 + std::min(left, 127)), char(rgbe[channel])};
    bytes.reserve(bytes.size() + scanline.size() * std::size_t(height));
    for (int row = 0; row < height; ++row) bytes += scanline;
    return bytes;
}

// The decoder is ptview's own (stb_image refuses images of more than 2^31 bytes as floats); it reads
// what stb_image reads, bit for bit, including its odd rule that a scanline without an RLE marker
// turns the whole image into flat pixels from the first one on.
TEST_F(EnvironmentMapFiles, DecodesEveryLayoutAsStbImageDoes) {
    std::mt19937 random(17);
    std::uniform_real_distribution<float> value(0.0f, 40.0f);
    auto randomMap = [&](int width, int height) {
        std::vector<float> rgb(std::size_t(width) * height * 3);
        for (float& v : rgb) v = value(random) * value(random);
        return rgb;
    };
    std::string rle = writeHdr("rle.hdr", 37, 5, randomMap(37, 5)); // width >= 8: run-length coded
    std::string flat = writeHdr("flat.hdr", 4, 3, randomMap(4, 3)); // narrower: flat
    // One RLE scanline (each channel a run of 8), then flat pixels for the whole image; and flat
    // from the first scanline on.
    const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 8\n";
    const std::string rleRow = {2, 2, 0, 8, char(0x88), 90, char(0x88), 60, char(0x88), 30, char(0x88), char(130)};
    std::string flatPixels;
    for (int t = 0; t < 16; ++t) flatPixels += {char(200 + t), char(10 + t), char(t), char(120 + t)};
    const std::string flatAfterRle = write("flat_after_rle.hdr", header + rleRow + flatPixels);
    const std::string flatFromStart = write("flat_from_start.hdr", header + flatPixels);
    for (const std::string& path : {rle, flat, flatAfterRle, flatFromStart}) {
        int width = 0, height = 0, channels = 0;
        float* expected = stbi_loadf(path.c_str(), &width, &height, &channels, 3);
        ASSERT_NE(expected, nullptr) << path;
        EnvironmentMap map = loadEnvironmentMap(path);
        ASSERT_EQ(map.width, width);
        ASSERT_EQ(map.height, height);
        EXPECT_EQ(map.rgb, std::vector<float>(expected, expected + std::size_t(width) * height * 3)) << path;
        stbi_image_free(expected);
    }
}

// Before: stb_image refused 16384 x 16384 ("too large"), the size the documentation promised.
TEST_F(EnvironmentMapFiles, LoadsTheLargestMapTheDocumentationPromises) {
    const unsigned char rgbe[4] = {128, 64, 32, 129}; // (1, 0.5, 0.25): m * 2^(e - 136)
    EnvironmentMap map = loadEnvironmentMap(write("largest.hdr", constantRleHdr(16384, 16384, rgbe)));
    ASSERT_EQ(map.width, 16384);
    ASSERT_EQ(map.height, 16384);
    for (std::size_t texel : {std::size_t(0), std::size_t(16384) * 8191 + 4000, std::size_t(16384) * 16384 - 1})
        EXPECT_EQ(glm::vec3(map.rgb[3 * texel], map.rgb[3 * texel + 1], map.rgb[3 * texel + 2]), glm::vec3(1.0f, 0.5f, 0.25f));
    EXPECT_NEAR(map.meanRadiance.x, 1.0, 1e-9);
    EXPECT_EQ(map.conditionalCdf.size(), std::size_t(16384) * 16384);
    EXPECT_EQ(map.marginalCdf.back(), 1.0f);
}

TEST_F(EnvironmentMapFiles, RefusesDevicesAndOversizedFilesUnread) {
    EXPECT_NE(loadError("/dev/zero").find("/dev/zero: cannot open environment map: a character device, not a regular file"),
              std::string::npos);
    // Sparse: larger than a flat 16384 x 16384 map and its header, and nothing on disk.
    const std::string huge = write("huge.hdr", "");
    fs::resize_file(huge, (std::uintmax_t(1) << 30) + (2u << 20));
    EXPECT_NE(loadError(huge).find("environment map too large (1026 MiB; at most 1025 MiB)"), std::string::npos);
}

// Before: a valid 8192 x 8192 map under a 1.7 GB address-space limit aborted on std::bad_alloc
// (with more memory: "ptview: std::bad_alloc", exit 1). Each allocation the map needs is an error
// naming the file and what did not fit.
TEST_F(EnvironmentMapFiles, MapBeyondTheMemoryLeftNamesTheFileAndWhatDidNotFit) {
#ifdef PTVIEW_UNDER_ASAN
    GTEST_SKIP() << "an address-space limit cannot be set under AddressSanitizer";
#endif
    const unsigned char rgbe[4] = {128, 128, 128, 129};
    const std::string path = write("large.hdr", constantRleHdr(8192, 8192, rgbe)); // 768 MiB of texels, 256 of CDF
    const rlim_t inUse = testing::addressSpaceInUse();
    ASSERT_GT(inUse, 0u);
    auto messageCode = [&](const std::string& expected) {
        return [&, expected] {
            try {
                loadEnvironmentMap(path);
            } catch (const EnvironmentMapError& e) {
                const std::string what = e.what();
                return what.rfind(path + ": ", 0) == 0 && what.find(expected) != std::string::npos ? 0 : 2;
            }
            return 1;
        };
    };
    // Room for the file's 8 MiB, not for the texels.
    testing::ChildExit texels = testing::runInLimitedChild(RLIMIT_AS, inUse + (256u << 20),
                                                           messageCode("not enough memory for its 8192x8192 texels (768 MiB)"));
    EXPECT_EQ(texels.signal, 0) << "killed by a signal: an abort";
    EXPECT_EQ(texels.code, 0) << "1: it loaded, 2: another message, 3: no limit";
    // Room for the texels, not for the sampling distribution.
    testing::ChildExit distribution = testing::runInLimitedChild(
        RLIMIT_AS, inUse + (900u << 20), messageCode("not enough memory for the sampling distribution"));
    EXPECT_EQ(distribution.signal, 0) << "killed by a signal: an abort";
    EXPECT_EQ(distribution.code, 0) << "1: it loaded, 2: another message, 3: no limit";
    // Memory follows what the file holds, not what its header claims: 60 bytes that claim
    // 16384 x 16384 texels (3 GiB) are refused as truncated within the same small limit.
    const std::string tiny = write("claims_16384.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 16384 +X 16384\n" +
                                                            std::string("\x02\x02\x40\x00\xff\x01", 6));
    testing::ChildExit claim = testing::runInLimitedChild(RLIMIT_AS, inUse + (256u << 20), [&] {
        try {
            loadEnvironmentMap(tiny);
        } catch (const EnvironmentMapError& e) {
            return std::string(e.what()) == tiny + ": truncated (the file ends inside scanline 0)" ? 0 : 2;
        }
        return 1;
    });
    EXPECT_EQ(claim.signal, 0);
    EXPECT_EQ(claim.code, 0) << "1: it loaded, 2: another message (not enough memory: allocated first), 3: no limit";
}

// A texel above the scene format's radiance bound (1e9) times an intensity within its range
// could overflow a float (a 1.7e38 RGBE texel is a valid file): refused like a NaN.
TEST_F(EnvironmentMapFiles, RefusesTexelsThatAreNotFiniteAndNonNegative) {
    for (float bad : {NAN, INFINITY, -1.0f, 2e9f, 1.7e38f}) {
        std::vector<float> rgb(4 * 2 * 3, 1.0f);
        rgb[3 * 5 + 1] = bad; // texel 5 = (1, 1)
        try {
            makeEnvironmentMap(4, 2, rgb, "memory.hdr");
            ADD_FAILURE() << bad << " accepted";
        } catch (const EnvironmentMapError& error) {
            EXPECT_EQ(std::string(error.what()).rfind("memory.hdr: texel (1, 1) has radiance ", 0), 0u) << error.what();
        }
    }
    EXPECT_THROW(makeEnvironmentMap(0, 1, {}, "empty"), EnvironmentMapError);
}

// ---- The scene format

std::string sceneWithEnvironment(const std::string& environment) {
    return R"({ "camera": { "eye": [0, 0, 3], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [8, 8] },
               "environment": )" + environment + R"(, "materials": {}, "shapes": [] })";
}

std::string sceneError(const std::string& environment) {
    try {
        parseScene(sceneWithEnvironment(environment), "s.json");
    } catch (const SceneError& error) {
        return error.what();
    }
    return "(loaded)";
}

TEST(EnvironmentSceneFormat, MapPathIsRelativeToTheSceneFile) {
    Scene scene = parseScene(sceneWithEnvironment(R"({ "map": "../hdr/sky.hdr" })"), "scenes/outdoor/s.json");
    EXPECT_EQ(scene.environmentMap, fs::path("scenes/outdoor/../hdr/sky.hdr"));
    EXPECT_EQ(scene.environmentIntensity, 1.0f);
    EXPECT_EQ(scene.environmentRotationDeg, 0.0f);
    EXPECT_EQ(scene.environment, glm::vec3(0.0f));

    scene = parseScene(sceneWithEnvironment(R"({ "map": "/maps/sky.hdr", "intensity": 2.5, "rotation_deg": -90 })"),
                       "scenes/s.json");
    EXPECT_EQ(scene.environmentMap, fs::path("/maps/sky.hdr"));
    EXPECT_EQ(scene.environmentIntensity, 2.5f);
    EXPECT_EQ(scene.environmentRotationDeg, -90.0f);

    scene = parseScene(sceneWithEnvironment(R"({ "map": "sky.hdr", "intensity": 0 })"), "s.json");
    EXPECT_EQ(scene.environmentMap, fs::path("sky.hdr"));
    EXPECT_EQ(scene.environmentIntensity, 0.0f);
}

TEST(EnvironmentSceneFormat, ColourOrMapNeverBoth) {
    EXPECT_EQ(sceneError(R"({ "color": [1, 1, 1], "map": "sky.hdr" })"),
              "s.json: /environment/color: not allowed with \"map\" (the map gives the radiance)");
    EXPECT_EQ(sceneError(R"({ "color": [1, 1, 1], "intensity": 2 })"), "s.json: /environment/intensity: only allowed with \"map\"");
    EXPECT_EQ(sceneError(R"({ "color": [1, 1, 1], "rotation_deg": 2 })"),
              "s.json: /environment/rotation_deg: only allowed with \"map\"");
    EXPECT_EQ(sceneError(R"({})"), "s.json: /environment/color: missing required key (or give \"map\")");
    EXPECT_EQ(sceneError(R"({ "map": "" })"), "s.json: /environment/map: expected a file name, got an empty string");
    EXPECT_EQ(sceneError(R"({ "map": 3 })"), "s.json: /environment/map: expected a string, got a number");
    EXPECT_EQ(sceneError(R"({ "map": "a.hdr", "intensity": -1 })"), "s.json: /environment/intensity: expected a number in [0, 1000000000]");
    EXPECT_EQ(sceneError(R"({ "map": "a.hdr", "rotation_deg": "east" })"),
              "s.json: /environment/rotation_deg: expected a number, got a string");
    EXPECT_EQ(sceneError(R"({ "map": "a.hdr", "scale": 2 })"),
              "s.json: /environment/scale: unknown key (expected one of: color, map, intensity, rotation_deg)");
}

TEST_F(EnvironmentMapFiles, WriterKeepsTheMapRelativeToTheFileItWrites) {
    fs::create_directories(dir_ / "scenes");
    fs::create_directories(dir_ / "hdr");
    fs::create_directories(dir_ / "elsewhere" / "deeper");
    const fs::path scenePath = dir_ / "scenes" / "s.json";
    Scene scene = parseScene(sceneWithEnvironment(R"({ "map": "../hdr/sky.hdr", "intensity": 0.7, "rotation_deg": 33.3 })"),
                             scenePath);

    std::string text = sceneToJson(scene);
    EXPECT_NE(text.find("\"environment\": {\n    \"map\": \"../hdr/sky.hdr\",\n    \"intensity\": 0.7,\n    \"rotation_deg\": 33.3\n  }"),
              std::string::npos)
        << text;
    Scene again = parseScene(text, scenePath);
    EXPECT_EQ(again.environmentMap, scene.environmentMap);
    EXPECT_EQ(again.environmentIntensity, scene.environmentIntensity);
    EXPECT_EQ(again.environmentRotationDeg, scene.environmentRotationDeg);

    // Saved elsewhere, the path is rewritten to reach the same file from there.
    const fs::path moved = dir_ / "elsewhere" / "deeper" / "s.json";
    saveScene(scene, moved);
    EXPECT_NE(fileBytes(moved.string()).find(R"("map": "../../hdr/sky.hdr")"), std::string::npos) << fileBytes(moved.string());
    Scene reloaded = loadScene(moved);
    EXPECT_EQ(fs::absolute(reloaded.environmentMap).lexically_normal(), (dir_ / "hdr" / "sky.hdr").lexically_normal());

    // A constant environment is written as before.
    EXPECT_NE(sceneToJson(parseScene(sceneWithEnvironment(R"({ "color": [1, 2, 3] })"), "s.json"))
                  .find(R"("environment": {"color": [1, 2, 3]})"),
              std::string::npos);
}

// ---- The density on the GPU: orientation

TEST(EnvironmentMapOrientation, TexelsLieWhereTheDocumentationSays) {
    // Every texel a different radiance; each texel's documented centre direction must read it back.
    const int width = 16, height = 8;
    std::vector<float> rgb;
    for (int t = 0; t < width * height; ++t) rgb.insert(rgb.end(), {float(t + 1), 0.0f, 0.0f});
    EnvironmentMap map = makeEnvironmentMap(width, height, rgb, "numbered");
    for (double rotationDeg : {0.0, 90.0, -37.5, 400.0}) {
        probe().setMap(map, 1.0f, float(rotationDeg));
        std::vector<glm::vec3> directions;
        for (int j = 0; j < height; ++j)
            for (int i = 0; i < width; ++i) directions.push_back(glm::vec3(texelCentreDirection(map, i, j, rotationDeg)));
        std::vector<ProbeEvaluation> read = probe().evaluate(directions);
        int wrong = 0;
        for (int t = 0; t < width * height; ++t)
            if (read[std::size_t(t)].radiance.r != float(t + 1) && ++wrong <= 3)
                ADD_FAILURE() << "rotation " << rotationDeg << ": texel (" << t % width << ", " << t / width << ") read "
                              << read[std::size_t(t)].radiance.r;
        EXPECT_EQ(wrong, 0) << "rotation " << rotationDeg;
    }

    // The named directions, by hand. Unrotated: the image's centre (u = 0.5) looks along -Z and
    // u = 0.75 along +X; the top row is +Y.
    auto texelSeenAlong = [&](glm::vec3 direction, float rotationDeg) {
        probe().setMap(map, 1.0f, rotationDeg);
        int t = int(probe().evaluate({glm::normalize(direction)})[0].radiance.r) - 1;
        return glm::ivec2(t % width, t / width);
    };
    EXPECT_EQ(texelSeenAlong({0.01f, 0.1f, -1.0f}, 0.0f), glm::ivec2(8, 3));  // -Z, just right of centre, above the horizon
    EXPECT_EQ(texelSeenAlong({-0.01f, -0.1f, -1.0f}, 0.0f), glm::ivec2(7, 4)); // -Z, just left, below
    EXPECT_EQ(texelSeenAlong({1.0f, 0.1f, 0.01f}, 0.0f), glm::ivec2(12, 3));  // +X turned toward +Z: u just above 0.75
    EXPECT_EQ(texelSeenAlong({0.0f, 1.0f, 0.0f}, 0.0f).y, 0);                 // straight up: top row
    EXPECT_EQ(texelSeenAlong({0.0f, -1.0f, 0.0f}, 0.0f).y, height - 1);        // straight down: bottom row
    // rotation_deg = 90 turns the map counter-clockwise seen from above (+Y toward the viewer):
    // its centre now looks along -X, and what looked along +X looks along -Z.
    EXPECT_EQ(texelSeenAlong({-1.0f, 0.1f, 0.01f}, 90.0f), glm::ivec2(7, 3));
    EXPECT_EQ(texelSeenAlong({-1.0f, 0.1f, -0.01f}, 90.0f), glm::ivec2(8, 3));
    EXPECT_EQ(texelSeenAlong({-0.01f, 0.1f, -1.0f}, 90.0f), glm::ivec2(11, 3));
}

TEST(EnvironmentMapOrientation, OneBrightTexelIsSampledInItsDocumentedDirection) {
    const int width = 64, height = 32;
    const glm::ivec2 bright(45, 11);
    std::vector<float> rgb(std::size_t(width * height) * 3, 0.0f);
    for (int c = 0; c < 3; ++c) rgb[std::size_t(bright.y * width + bright.x) * 3 + std::size_t(c)] = 10.0f;
    EnvironmentMap map = makeEnvironmentMap(width, height, rgb, "one texel");
    for (float rotationDeg : {0.0f, 90.0f, 200.0f}) {
        probe().setMap(map, 3.0f, rotationDeg);
        int outside = 0;
        for (const ProbeSample& s : probe().sample(uniformPoints(20000, 5))) {
            glm::ivec2 texel = texelOf(map, documentedUv(glm::dvec3(s.direction), rotationDeg));
            bool ok = texel == bright && s.radiance == glm::vec3(30.0f) && s.pdf > 0.0f;
            if (!ok && ++outside <= 3)
                ADD_FAILURE() << "rotation " << rotationDeg << ": sample in texel (" << texel.x << ", " << texel.y
                              << "), radiance " << s.radiance.r << ", pdf " << s.pdf;
        }
        EXPECT_EQ(outside, 0);
    }
}

// ---- The density on the GPU: sampling

TEST(EnvironmentMapSampling, SunlitParkFollowsTheDensity) {
    chiSquareOverDirections(rooitou(), 0.0, {64, 32}, 1000000, 11, "rooitou_park 64x32 bins");
}

TEST(EnvironmentMapSampling, SunlitParkFollowsTheDensityTexelByTexelAroundTheSun) {
    // Each texel of a 32x32 window around the sun is a bin (the sun's few texels hold most of the
    // samples), and all the rest one more. Binned by the sampled map coordinates: directions cross
    // texel edges in float rounding, which would move a few of the sun's samples to its neighbours.
    const EnvironmentMap& map = rooitou();
    probe().setMap(map);
    const glm::ivec2 corner(614 - 16, 226 - 16);
    const int window = 32;
    auto binOf = [&](glm::ivec2 t) {
        glm::ivec2 local = t - corner;
        bool inside = local.x >= 0 && local.y >= 0 && local.x < window && local.y < window;
        return inside ? std::size_t(local.y * window + local.x) : std::size_t(window * window);
    };
    const int sampleCount = 1000000;
    std::vector<double> probability = texelProbabilities(map, 0.0);
    std::vector<double> expected(std::size_t(window * window + 1), 0.0), observed(expected.size(), 0.0);
    for (int j = 0; j < map.height; ++j)
        for (int i = 0; i < map.width; ++i)
            expected[binOf({i, j})] += probability[std::size_t(j) * std::size_t(map.width) + std::size_t(i)] * sampleCount;
    for (const ProbeSample& s : probe().sample(uniformPoints(sampleCount, 12)))
        observed[binOf(texelOf(map, glm::dvec2(s.uv)))] += 1.0;
    std::printf("  share of samples within the 32x32 texels around the sun: %.3f\n",
                1.0 - observed.back() / sampleCount);
    expectChiSquareFit(observed, expected, "rooitou_park sun window, per texel", [&](std::size_t bin) {
        if (bin == std::size_t(window * window)) return std::string("rest of the map");
        return "texel (" + std::to_string(corner.x + int(bin) % window) + ", " + std::to_string(corner.y + int(bin) / window) + ")";
    });
}

TEST(EnvironmentMapSampling, RotatedSyntheticMapFollowsTheDensityWithinTexels) {
    EnvironmentMap map = syntheticMap(32, 16, 7);
    // 2 x 2 bins per texel.
    chiSquareOverDirections(map, 37.0, {64, 32}, 400000, 13, "synthetic 32x16, rotated 37 deg, 64x32 bins");
}

TEST(EnvironmentMapSampling, StudioWithSeveralLightsFollowsTheDensity) {
    chiSquareOverDirections(loadEnvironmentMap(kStudio), -120.0, {64, 32}, 400000, 14, "studio_small_03 64x32 bins, -120 deg");
}

TEST(EnvironmentMapSampling, DensityIntegratesToOne) {
    // A midpoint rule on the equal-area chart (y = cos theta, phi), dy dphi = d omega, so the
    // density is integrated as it is (its 1 / sin(theta) included). The synthetic map's 2048 x 2048
    // cells are aligned with nothing. The park's sun is 2 texels holding most of the probability,
    // so its cells are aligned with the texel rows (each row's y range cut into 8) and columns
    // (4 per column): misaligned, a cell cut by a sun texel's edge moves percents of probability.
    const EnvironmentMap synthetic = syntheticMap(32, 16, 7);
    struct Case {
        const EnvironmentMap* map;
        float rotationDeg;
        std::vector<double> yEdges; // cell rows, from -1 to 1
        int columns;
        double tolerance;
    };
    std::vector<double> uniformEdges, rowEdges;
    for (int k = 0; k <= 2048; ++k) uniformEdges.push_back(-1.0 + 2.0 * k / 2048);
    for (int j = rooitou().height; j > 0; --j)
        for (int k = 0; k < 8; ++k) rowEdges.push_back(std::cos(kPi * (j - k / 8.0) / rooitou().height));
    rowEdges.push_back(1.0);
    for (const Case& c : {Case{&synthetic, 37.0f, uniformEdges, 2048, 2e-3}, Case{&rooitou(), 0.0f, rowEdges, 4 * 1024, 1e-3}}) {
        probe().setMap(*c.map, 1.0f, c.rotationDeg);
        double integral = 0.0;
        std::vector<glm::vec3> points;
        std::vector<double> weights;
        const double dphi = 2.0 * kPi / c.columns;
        for (std::size_t row = 0; row + 1 < c.yEdges.size(); ++row) {
            double dy = c.yEdges[row + 1] - c.yEdges[row];
            double y = 0.5 * (c.yEdges[row] + c.yEdges[row + 1]), r = std::sqrt(1.0 - y * y);
            for (int column = 0; column < c.columns; ++column) {
                double phi = (column + 0.5) * dphi;
                points.emplace_back(float(r * std::cos(phi)), float(y), float(r * std::sin(phi)));
                weights.push_back(dy * dphi);
            }
            if (points.size() >= (1u << 20) || row + 2 == c.yEdges.size()) {
                std::vector<ProbeEvaluation> density = probe().evaluate(points);
                for (std::size_t k = 0; k < density.size(); ++k) integral += double(density[k].pdf) * weights[k];
                points.clear();
                weights.clear();
            }
        }
        std::printf("  %-28s integral of the density over the sphere = %.6f\n", c.map->source.c_str(), integral);
        EXPECT_NEAR(integral, 1.0, c.tolerance) << c.map->source;
    }
}

TEST(EnvironmentMapSampling, SampledDirectionsHaveTheDensityOfTheirTexel) {
    // The density of the texel the sampler drew equals environmentMapPdf of the direction it
    // returns, up to float rounding, except where that rounding moves the direction across a texel
    // edge: only samples within 1e-3 texel of an edge may differ. The sampler reports the latter.
    // Every sample is finite; its drawn texel is never black; its density is positive except
    // exactly at a pole or across an edge. The same holds for u exactly on each CDF value and on 0
    // (after the random ones): a row or column that starts with black texels repeats the value 0,
    // which only a strict search skips, and one that ends with them reaches 1 early (u = 1 is
    // outside the sampler's [0, 1), but must not give a NaN either).
    const EnvironmentMap synthetic = syntheticMap(32, 16, 9);
    for (const EnvironmentMap* map : {&rooitou(), &synthetic}) {
        probe().setMap(*map, 1.0f, 123.0f);
        int differ = 0, differAwayFromEdges = 0, bad = 0;
        const int randomCount = 400000;
        std::vector<glm::vec2> u = uniformPoints(randomCount, 21);
        for (int j = 0; j < map->height; ++j) {
            float rowStart = j > 0 ? map->marginalCdf[std::size_t(j) - 1] : 0.0f;
            u.emplace_back(0.0f, rowStart);
            for (int i = 0; i + 1 < map->width; ++i)
                u.emplace_back(map->conditionalCdf[std::size_t(j) * std::size_t(map->width) + std::size_t(i)], rowStart);
        }
        const std::vector<ProbeSample> samples = probe().sample(u);
        for (std::size_t k = 0; k < samples.size(); ++k) {
            const ProbeSample& s = samples[k];
            auto fail = [&](const std::string& what) {
                if (++bad <= 3)
                    ADD_FAILURE() << map->source << ": u = (" << u[k].x << ", " << u[k].y << ") gave uv (" << s.uv.x << ", "
                                  << s.uv.y << "), pdf " << s.pdf << ": " << what;
            };
            bool finite = std::isfinite(s.pdf) && std::isfinite(s.pdfEval) && std::isfinite(s.direction.x) &&
                          std::isfinite(s.direction.y) && std::isfinite(s.direction.z) && std::isfinite(s.radiance.r) &&
                          s.uv.x >= 0.0f && s.uv.x <= 1.0f && s.uv.y >= 0.0f && s.uv.y <= 1.0f;
            if (!finite) {
                fail("not finite");
                continue;
            }
            if (u[k].x >= 1.0f) continue; // outside the contract: only finite
            glm::ivec2 texel = texelOf(*map, glm::dvec2(s.uv));
            if (texelRadiance(*map, texel.x, texel.y) == glm::vec3(0.0f)) fail("drew a black texel");
            if (s.pdf != s.pdfEval) fail("the sampler's density is not environmentMapPdf(direction)");
            glm::vec2 inTexel = glm::fract(s.uv * glm::vec2(map->width, map->height));
            float edge = std::min(std::min(inTexel.x, 1.0f - inTexel.x), std::min(inTexel.y, 1.0f - inTexel.y));
            bool atPole = s.uv.y == 0.0f || s.uv.y >= 1.0f;
            if (!(s.pdf > 0.0f) && !atPole && edge > 1e-3f) fail("pdf 0 away from the poles and texel edges");
            if (k >= std::size_t(randomCount) || atPole || std::abs(s.drawnPdf() - s.pdfEval) <= 2e-5 * s.drawnPdf()) continue;
            ++differ;
            if (edge > 1e-3f && ++differAwayFromEdges <= 3)
                ADD_FAILURE() << map->source << ": drawn texel's pdf " << s.drawnPdf() << ", environmentMapPdf " << s.pdfEval
                              << " at uv (" << s.uv.x << ", " << s.uv.y << ")";
        }
        std::printf("  %-40s %d of %d samples rounded across a texel edge\n", map->source.c_str(), differ, randomCount);
        EXPECT_EQ(bad, 0);
        EXPECT_EQ(differAwayFromEdges, 0);
        EXPECT_LT(differ, randomCount / 1000);
    }
}

TEST(EnvironmentMapSampling, PolesGiveNoNaN) {
    // Light only in the rows that touch the poles.
    const int width = 16, height = 8;
    std::vector<float> rgb(std::size_t(width * height) * 3, 0.0f);
    for (int i = 0; i < width; ++i)
        for (int c = 0; c < 3; ++c) {
            rgb[std::size_t(i) * 3 + std::size_t(c)] = 1.0f + float(i);
            rgb[std::size_t((height - 1) * width + i) * 3 + std::size_t(c)] = 2.0f;
        }
    probe().setMap(makeEnvironmentMap(width, height, rgb, "poles"));
    std::vector<glm::vec2> u = uniformPoints(100000, 3);
    // The corners of the unit square: u = 0 lands exactly on the north pole.
    for (float a : {0.0f, 0.99999994f})
        for (float b : {0.0f, 0.99999994f}) u.emplace_back(a, b);
    int bad = 0;
    for (const ProbeSample& s : probe().sample(u)) {
        bool ok = std::isfinite(s.pdf) && s.pdf >= 0.0f && std::isfinite(s.pdfEval) && std::isfinite(s.direction.x) &&
                  std::isfinite(s.direction.y) && std::isfinite(s.direction.z) && std::abs(glm::length(s.direction) - 1.0f) < 1e-5f &&
                  std::abs(s.direction.y) > 0.9f; // the top or bottom row
        if (!ok && ++bad <= 3)
            ADD_FAILURE() << "direction (" << s.direction.x << ", " << s.direction.y << ", " << s.direction.z << "), pdf "
                          << s.pdf << ", environmentMapPdf " << s.pdfEval;
    }
    EXPECT_EQ(bad, 0);
    std::vector<ProbeEvaluation> poles = probe().evaluate({{0.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}});
    EXPECT_EQ(poles[0].pdf, 0.0f);
    EXPECT_EQ(poles[1].pdf, 0.0f);
    EXPECT_EQ(poles[0].radiance, glm::vec3(1.0f)); // texel (0, 0): azimuth 0 at the pole
    EXPECT_EQ(poles[1].radiance, glm::vec3(2.0f));
}

// ---- Rendering

class EnvironmentMapRender : public EnvironmentMapFiles {
protected:
    static ImageRgbF render(const Scene& scene, RenderSettings settings, int samplesPerPixel, PixelStatistics* stats = nullptr) {
        testing::glContext();
        PathTracer tracer;
        tracer.setScene(scene);
        tracer.setImageSize(scene.camera.resolution);
        tracer.setSettings(settings);
        for (int i = 0; i < samplesPerPixel; ++i) tracer.renderSample();
        if (stats) *stats = tracer.readStatistics();
        return tracer.readMean();
    }
    Scene sphereUnder(const std::string& mapPath, float intensity, float rotationDeg, int size) {
        return parseScene(R"({ "camera": { "eye": [0, 0, 4], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [)" +
                              std::to_string(size) + ", " + std::to_string(size) + R"(] },
            "environment": { "map": ")" + mapPath + R"(", "intensity": )" + std::to_string(intensity) +
                              R"(, "rotation_deg": )" + std::to_string(rotationDeg) + R"( },
            "materials": { "white": { "type": "diffuse", "albedo": [1, 1, 1] } },
            "shapes": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "white" } ] })",
                          dir_ / "scene.json");
    }
};

TEST_F(EnvironmentMapRender, WhiteSphereInUniformLightIsExactlyAsBrightAsTheSky) {
    // Albedo 1 on a convex sphere: every bounce escapes, and the naive sample weight is exactly 1.
    writeHdr("uniform.hdr", 2, 1, {1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f});
    ImageRgbF image = render(sphereUnder("uniform.hdr", 1.0f, 0.0f, 32), testing::naiveSettings(8, 1), 8);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(image.at(x, y)[c], 1.0f, 1e-5f) << x << ", " << y;

    // intensity scales it, and every integrator agrees: the ones that sample the map as a light
    // (not exact per sample) average to the same 2 over the sphere's inner pixels, within 4
    // standard errors.
    for (Integrator integrator : {Integrator::Naive, Integrator::Direct, Integrator::Mis, Integrator::Full}) {
        RenderSettings settings = testing::naiveSettings(8, 2);
        settings.integrator = integrator;
        PixelStatistics stats;
        render(sphereUnder("uniform.hdr", 2.0f, 0.0f, 32), settings, 256, &stats);
        double sum = 0.0, variance = 0.0;
        int pixels = 0;
        for (int y = 10; y < 22; ++y)
            for (int x = 10; x < 22; ++x) {
                sum += stats.mean.at(x, y).g;
                variance += stats.varianceOfMean.at(x, y).g;
                ++pixels;
            }
        double mean = sum / pixels, standardError = std::sqrt(variance) / pixels;
        std::printf("  %-8s sphere pixels average %.4f +- %.4f\n", integratorName(integrator), mean, standardError);
        EXPECT_NEAR(mean, 2.0, 4.0 * standardError + 1e-5) << integratorName(integrator);
    }
}

TEST_F(EnvironmentMapRender, CameraSeesTheMapAsDocumented) {
    // Four columns of different colours. Looking along -Z the image's centre (u = 0.5) is in the
    // middle of the view: column 1 on the left, column 2 on the right; at 90 degrees of rotation
    // -Z sees what was along +X (u = 0.75): column 2 on the left, column 3 on the right.
    const glm::vec3 colours[4] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
    std::vector<float> rgb;
    for (int j = 0; j < 2; ++j)
        for (const glm::vec3& c : colours) rgb.insert(rgb.end(), {c.r, c.g, c.b});
    writeHdr("columns.hdr", 4, 2, rgb);
    for (float rotationDeg : {0.0f, 90.0f}) {
        Scene scene = parseScene(R"({ "camera": { "eye": [0, 0, 0], "target": [0, 0.1, -1], "vfov_deg": 20, "resolution": [16, 8] },
            "environment": { "map": "columns.hdr", "rotation_deg": )" + std::to_string(rotationDeg) + R"( },
            "materials": {}, "shapes": [] })",
                                 dir_ / "scene.json");
        ImageRgbF image = render(scene, testing::naiveSettings(1, 1), 4);
        int left = rotationDeg == 0.0f ? 1 : 2;
        EXPECT_EQ(image.at(2, 4), colours[left]) << rotationDeg;
        EXPECT_EQ(image.at(13, 4), colours[left + 1]) << rotationDeg;
    }
}

// Irradiance (luminance) E(n) = integral of L cos over the hemisphere around n, from the map's
// texels: each texel's luminance times its exact solid angle, times the cosine at its centre.
class Irradiance {
public:
    Irradiance(const EnvironmentMap& map, double rotationDeg, double intensity) {
        for (int j = 0; j < map.height; ++j) {
            double solidAngle = 2.0 * kPi / map.width * (std::cos(kPi * j / map.height) - std::cos(kPi * (j + 1) / map.height));
            for (int i = 0; i < map.width; ++i) {
                glm::vec3 radiance = texelRadiance(map, i, j);
                double luminance = 0.2126 * radiance.r + 0.7152 * radiance.g + 0.0722 * radiance.b;
                texels_.push_back({texelCentreDirection(map, i, j, rotationDeg), luminance * solidAngle * intensity});
            }
        }
    }
    double operator()(glm::dvec3 normal) const {
        double sum = 0.0;
        for (const Texel& t : texels_) sum += t.power * std::max(0.0, glm::dot(normal, t.direction));
        return sum;
    }

private:
    struct Texel {
        glm::dvec3 direction;
        double power;
    };
    std::vector<Texel> texels_;
};

TEST_F(EnvironmentMapRender, SunlitWhiteSphereMatchesTheIrradianceOfTheMap) {
    // A white Lambertian sphere reflects E(n) / pi at the point of normal n, which a few sums
    // over the map give. The full integrator must agree, with the sun (65,000 times the median
    // texel) found by light sampling and MIS-weighted against BSDF sampling. Rotated by 180 degrees,
    // the sun stands to the camera's left at 10 degrees elevation.
    const int size = 96;
    Scene scene = sphereUnder(kRooitou, 0.5f, 180.0f, size);
    RenderSettings settings = testing::naiveSettings(4, 3);
    settings.integrator = Integrator::Full;
    PixelStatistics stats;
    render(scene, settings, 1024, &stats);

    const CameraDesc& camera = scene.camera;
    glm::dvec3 eye(camera.eye), forward = glm::normalize(glm::dvec3(camera.target) - eye);
    glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(camera.up))), up = glm::cross(right, forward);
    double tanHalf = std::tan(glm::radians(double(camera.vfovDeg)) / 2.0);
    const Irradiance irradiance(rooitou(), 180.0, 0.5);
    int checked = 0;
    for (glm::ivec2 pixel : {glm::ivec2(48, 48), glm::ivec2(30, 40), glm::ivec2(22, 50), glm::ivec2(66, 30),
                             glm::ivec2(48, 70), glm::ivec2(40, 22), glm::ivec2(70, 60)}) {
        // The pixel's mean over its area: the normal at 4x4 points of the footprint.
        double expected = 0.0;
        for (int sy = 0; sy < 4; ++sy)
            for (int sx = 0; sx < 4; ++sx) {
                double fx = (pixel.x + (sx + 0.5) / 4.0) / size * 2.0 - 1.0;
                double fy = 1.0 - (pixel.y + (sy + 0.5) / 4.0) / size * 2.0; // image row 0 is the top
                glm::dvec3 d = glm::normalize(forward + fx * tanHalf * right + fy * tanHalf * up);
                double b = glm::dot(eye, d), c = glm::dot(eye, eye) - 1.0;
                ASSERT_GT(b * b - c, 0.0) << "pixel misses the sphere";
                glm::dvec3 normal = glm::normalize(eye + (-b - std::sqrt(b * b - c)) * d);
                expected += irradiance(normal) / kPi / 16.0;
            }
        glm::vec3 mean = stats.mean.at(pixel.x, pixel.y);
        double measured = 0.2126 * mean.r + 0.7152 * mean.g + 0.0722 * mean.b;
        glm::vec3 variance = stats.varianceOfMean.at(pixel.x, pixel.y);
        // The channels come from the same paths: their errors add, at worst, in full.
        double sigma = 0.2126 * std::sqrt(variance.r) + 0.7152 * std::sqrt(variance.g) + 0.0722 * std::sqrt(variance.b);
        std::printf("  pixel (%2d, %2d): rendered %.4f +- %.4f, expected %.4f\n", pixel.x, pixel.y, measured, sigma, expected);
        EXPECT_NEAR(measured, expected, 4.0 * sigma + 0.01 * expected) << "pixel " << pixel.x << ", " << pixel.y;
        ++checked;
    }
    EXPECT_EQ(checked, 7);
}

TEST_F(EnvironmentMapRender, RenderCommandRefusesABadMapNamingIt) {
    const std::string scene = (dir_ / "scene.json").string();
    std::ofstream(scene) << R"({ "camera": { "eye": [0, 0, 3], "target": [0, 0, 0], "vfov_deg": 40, "resolution": [8, 8] },
        "environment": { "map": "missing.hdr" }, "materials": {}, "shapes": [] })";
    const std::string out = (dir_ / "out.png").string();
    testing::CommandResult result =
        testing::runCommand(std::string(PTVIEW_BINARY) + " render " + testing::shellQuoted(scene) + " --out " + testing::shellQuoted(out));
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_EQ(result.output, "ptview: " + (dir_ / "missing.hdr").string() +
                                 ": cannot open environment map: No such file or directory\n");
    EXPECT_FALSE(fs::exists(out));

    write("missing.hdr", fileBytes(kRooitou).substr(0, 5000));
    result = testing::runCommand(std::string(PTVIEW_BINARY) + " render " + testing::shellQuoted(scene) + " --out " +
                                 testing::shellQuoted(out));
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_EQ(result.output.rfind("ptview: " + (dir_ / "missing.hdr").string() + ": truncated", 0), 0u) << result.output;
    EXPECT_FALSE(fs::exists(out));
}

} // namespace
} // namespace ptview
