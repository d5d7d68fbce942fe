// `ptview converge` on a tiny scene and budget: the CSV's MSE falls as 1/spp for an unbiased
// configuration, errors against a reference of another seed are never zero, and a biased
// configuration (one bounce against a deep reference) is reported as such, not hidden.
#include <ptview/metrics/ErrorMetrics.h>
#include <ptview/io/ImageIO.h>
#include "RunCommand.h"
#include "TestFiles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <unistd.h>

namespace ptview {
namespace {

namespace fs = std::filesystem;

struct Row {
    int spp;
    double seconds;
    double relativeMse;
    double rmse;
};

std::map<std::string, std::vector<Row>> readCsv(const fs::path& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "config,integrator,sampler,depth,spp,seconds,rmse,rel_mse,bias_r,bias_g,bias_b,nonfinite_share");
    std::map<std::string, std::vector<Row>> rows;
    while (std::getline(in, line)) {
        std::vector<std::string> fields;
        std::stringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');) fields.push_back(cell);
        EXPECT_EQ(fields.size(), 12u) << line;
        if (fields.size() != 12) continue;
        rows[fields[0]].push_back(Row{std::stoi(fields[4]), std::stod(fields[5]), std::stod(fields[7]), std::stod(fields[6])});
    }
    return rows;
}

// Least-squares slope of log(relMSE) against log(spp) over rows with spp >= from.
double slope(const std::vector<Row>& rows, int from) {
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const Row& row : rows) {
        if (row.spp < from) continue;
        double x = std::log(double(row.spp)), y = std::log(row.relativeMse);
        n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

TEST(Converge, UnbiasedErrorFallsAsOneOverSppAndBiasIsReported) {
    fs::path out = fs::temp_directory_path() / ("ptview_converge_" + std::to_string(::getpid()));
    fs::remove_all(out);
    // The reference has 32 times the samples of the longest run, so its own noise is small
    // beside the runs' errors and the MSE of an unbiased run falls as 1/spp.
    testing::CommandResult result = testing::runCommand(
        std::string(PTVIEW_BINARY) + " converge " + testing::shellQuoted(PTVIEW_ASSETS_DIR "/scenes/cornell.json") +
        " --out " + testing::shellQuoted(out.string()) +
        " --size 24x24 --reference-spp 2048 --max-spp 64 --time-budget 60 --configs full/random/4,full/random/1");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    std::map<std::string, std::vector<Row>> rows = readCsv(out / "convergence.csv");
    ASSERT_EQ(rows.size(), 2u);
    const std::vector<Row>& unbiased = rows["full/random/4"];
    const std::vector<Row>& oneBounce = rows["full/random/1"];
    ASSERT_EQ(unbiased.size(), 7u) << "checkpoints at 1, 2, 4, ..., 64 spp";
    for (const Row& row : unbiased) {
        EXPECT_GT(row.relativeMse, 0.0) << "a reference of another seed never matches exactly";
        EXPECT_GT(row.seconds, 0.0);
    }
    EXPECT_NEAR(slope(unbiased, 4), -1.0, 0.2);
    EXPECT_LT(unbiased.back().relativeMse, 0.1 * unbiased.front().relativeMse);

    // One bounce against a deep reference: the error levels off far above the unbiased one's.
    EXPECT_GT(slope(oneBounce, 8), -0.3);
    EXPECT_GT(oneBounce.back().relativeMse, 5.0 * unbiased.back().relativeMse);
    std::string summary = testing::readFileBytes(out / "summary.md");
    std::istringstream lines(summary);
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("| full/random/1 |", 0) == 0) { EXPECT_NE(line.find("**biased**"), std::string::npos) << line; }
        if (line.rfind("| full/random/4 |", 0) == 0) { EXPECT_EQ(line.find("biased"), std::string::npos) << line; }
    }
    EXPECT_NE(summary.find("seed"), std::string::npos) << "the summary says how the reference was made";
    EXPECT_TRUE(fs::exists(out / "reference.pfm"));
    EXPECT_GT(fs::file_size(out / "convergence.png"), 1000u) << result.output;

    // The reference can also be given: the same measurement against the file just written.
    fs::path again = out / "again";
    result = testing::runCommand(std::string(PTVIEW_BINARY) + " converge " +
                                 testing::shellQuoted(PTVIEW_ASSETS_DIR "/scenes/cornell.json") + " --out " +
                                 testing::shellQuoted(again.string()) + " --reference " +
                                 testing::shellQuoted((out / "reference.pfm").string()) +
                                 " --max-spp 4 --configs naive/sobol/4");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(readCsv(again / "convergence.csv")["naive/sobol/4"].size(), 3u);
    fs::remove_all(out);
}

// A firefly source: a small bright bulb seen through a glass pane. The floor under the pane gets
// its light only from BSDF samples that pass the pane and hit the bulb (light sampling is blocked
// by the glass): rarely (4% of paths) and brightly (15 per hit). Clamping each vertex's
// contribution to 1 removes the fireflies, and their energy: at low spp its error is lower than
// the unclamped one's, but it stops falling, and converge says so.
TEST(Converge, AClampedConfigurationCutsFirefliesAndIsReportedBiased) {
    fs::path out = fs::temp_directory_path() / ("ptview_converge_clamp_" + std::to_string(::getpid()));
    fs::remove_all(out);
    const std::string scene = testing::shellQuoted(PTVIEW_TEST_DATA_DIR "/caustic_fireflies.json");
    testing::CommandResult result = testing::runCommand(
        std::string(PTVIEW_BINARY) + " converge " + scene + " --out " + testing::shellQuoted(out.string()) +
        " --size 24x24 --reference-spp 2048 --max-spp 64 --time-budget 60 --configs full/random/8,full/random/8/clamp=1");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    std::map<std::string, std::vector<Row>> rows = readCsv(out / "convergence.csv");
    const std::vector<Row>& unclamped = rows["full/random/8"];
    const std::vector<Row>& clamped = rows["full/random/8/clamp=1"];
    ASSERT_EQ(unclamped.size(), 7u);
    ASSERT_EQ(clamped.size(), 7u);
    for (std::size_t i = 0; i < 3; ++i) // 1, 2 and 4 spp
        EXPECT_LT(clamped[i].rmse, unclamped[i].rmse) << clamped[i].spp << " spp";
    EXPECT_GT(slope(clamped, 8), -0.5) << "the clamped error levels off";
    std::string summary = testing::readFileBytes(out / "summary.md");
    std::istringstream lines(summary);
    bool found = false;
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("| full/random/8/clamp=1 |", 0) == 0) {
            found = true;
            EXPECT_NE(line.find("**biased**"), std::string::npos) << line;
        } else if (line.rfind("| full/random/8 |", 0) == 0) {
            EXPECT_EQ(line.find("biased"), std::string::npos) << line;
        }
    EXPECT_TRUE(found) << summary;

    // The brightest pixel of a render at 8 spp, with and without the clamp (ptview render --clamp).
    auto brightest = [&](const std::string& name, const std::string& options) {
        testing::CommandResult render = testing::runCommand(std::string(PTVIEW_BINARY) + " render " + scene + " --out " +
                                                            testing::shellQuoted((out / name).string()) +
                                                            " --size 24x24 --spp 8 --seed 2" + options);
        EXPECT_EQ(render.exitCode, 0) << render.output;
        ImageRgbF image = readPfm(out / name);
        float largest = 0.0f;
        for (float v : image.rgb) largest = std::max(largest, v);
        return largest;
    };
    float peakUnclamped = brightest("unclamped.pfm", "");
    float peakClamped = brightest("clamped.pfm", " --clamp 1");
    EXPECT_LT(peakClamped, peakUnclamped);
    EXPECT_GT(peakUnclamped, 1.0f) << "a firefly: one sample of ~15 over 8";
    fs::remove_all(out);
}

TEST(Converge, BadConfigurationsAreRefused) {
    testing::CommandResult result = testing::runCommand(std::string(PTVIEW_BINARY) + " converge " +
                                                        testing::shellQuoted(PTVIEW_ASSETS_DIR "/scenes/cornell.json") +
                                                        " --out /tmp/never --configs fast/random/8");
    EXPECT_EQ(result.exitCode, 2);
    EXPECT_NE(result.output.find("bad configuration \"fast/random/8\""), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists("/tmp/never/convergence.csv"));
}

// "/denoise" is the word alone or "denoise=" a filter's name, once: another value, another word
// after the depth, a repeat or a suffix in place of the depth is refused (exit 2) naming the configuration, before any rendering.
TEST(Converge, BadDenoiseSuffixesAreRefused) {
    testing::ScratchFiles files("converge_bad_denoise");
    const fs::path out = files.directory() / "out";
    for (const std::string config : {"full/sobol/8/denoise=x", "full/sobol/8/denoise=", "full/sobol/8/denoise=atrous/denoise",
                                     "full/sobol/8/denoised", "full/sobol/8/fast",
                                     "full/sobol/8/denoise/denoise", "full/sobol/denoise", "full/sobol/8/denoise/",
                                     "full/sobol/8/clamp=0/denoise"}) {
        testing::CommandResult result = testing::runCommand(
            std::string(PTVIEW_BINARY) + " converge " + testing::shellQuoted(PTVIEW_ASSETS_DIR "/scenes/cornell.json") +
            " --out " + testing::shellQuoted(out.string()) + " --size 8x8 --configs full/sobol/8," + config);
        EXPECT_EQ(result.exitCode, 2) << config << ": " << result.output;
        EXPECT_NE(result.output.find("bad configuration \"" + config + "\""), std::string::npos) << result.output;
        EXPECT_EQ(result.output.find("rendering the reference"), std::string::npos) << result.output;
    }
    EXPECT_FALSE(fs::exists(out / "convergence.csv"));
}

// "/denoise" parses after the depth, with or without a clamp and in either order, and names the
// configuration the same way whichever order it was given in; "/denoise=regression" picks the
// other filter, "/denoise=atrous" is "/denoise".
TEST(Converge, DenoiseSuffixParsesAloneAndWithAClamp) {
    testing::ScratchFiles files("converge_denoise_parse");
    const fs::path out = files.directory() / "out";
    testing::CommandResult result = testing::runCommand(
        std::string(PTVIEW_BINARY) + " converge " + testing::shellQuoted(PTVIEW_ASSETS_DIR "/scenes/cornell.json") +
        " --out " + testing::shellQuoted(out.string()) +
        " --size 8x8 --reference-spp 4 --max-spp 2 --configs mis/random/2/denoise,full/sobol/4/denoise/clamp=2,"
        "full/sobol/3/denoise=regression,full/sobol/2/denoise=atrous");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    std::map<std::string, std::vector<Row>> rows = readCsv(out / "convergence.csv");
    EXPECT_EQ(rows["mis/random/2/denoise"].size(), 2u) << "checkpoints at 1 and 2 spp";
    EXPECT_EQ(rows["full/sobol/4/clamp=2/denoise"].size(), 2u);
    EXPECT_EQ(rows["full/sobol/3/denoise=regression"].size(), 2u) << "a filter other than the default is named";
    EXPECT_EQ(rows["full/sobol/2/denoise"].size(), 2u) << "the default filter is named as before";
    EXPECT_EQ(rows.size(), 4u);
}

// "/adaptive=E" takes E in (0, 1], once, and not with the grid sampler (exit 2 before rendering);
// it runs the adaptive sampler with a checkpoint at each of its checks, the mean spp its spp, on
// the same time axis as the uniform configuration beside it.
TEST(Converge, AdaptiveSuffixIsCheckedAndMeasuredBesideTheUniformOne) {
    testing::ScratchFiles files("converge_adaptive");
    const fs::path out = files.directory() / "out";
    const std::string converge = std::string(PTVIEW_BINARY) + " converge " +
                                 testing::shellQuoted(PTVIEW_ASSETS_DIR "/scenes/cornell.json") + " --out " +
                                 testing::shellQuoted(out.string());
    for (const std::string config : {"full/sobol/8/adaptive=0", "full/sobol/8/adaptive=1.5", "full/sobol/8/adaptive=nan",
                                     "full/sobol/8/adaptive=", "full/sobol/8/adaptive=-0.1", "full/grid/8/adaptive=0.05",
                                     "full/sobol/8/adaptive=0.05/adaptive=0.05"}) {
        testing::CommandResult result = testing::runCommand(converge + " --size 8x8 --configs full/sobol/8," + config);
        EXPECT_EQ(result.exitCode, 2) << config << ": " << result.output;
        EXPECT_NE(result.output.find("bad configuration \"" + config + "\""), std::string::npos) << result.output;
        EXPECT_EQ(result.output.find("rendering the reference"), std::string::npos) << result.output;
    }
    testing::CommandResult result = testing::runCommand(
        converge + " --size 16x16 --reference-spp 256 --max-spp 256 --configs full/sobol/4,full/sobol/4/adaptive=0.1");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    std::map<std::string, std::vector<Row>> rows = readCsv(out / "convergence.csv");
    ASSERT_EQ(rows.size(), 2u);
    const std::vector<Row>& adaptive = rows["full/sobol/4/adaptive=0.1"];
    ASSERT_GE(adaptive.size(), 2u) << result.output;
    for (size_t i = 1; i < adaptive.size(); ++i) {
        EXPECT_GT(adaptive[i].seconds, adaptive[i - 1].seconds);
        EXPECT_GE(adaptive[i].spp, adaptive[i - 1].spp);
        EXPECT_LE(adaptive[i].spp, 256);
    }
}

// A /denoise configuration renders like the one without it and measures the denoised image at
// each checkpoint, the denoising counted in its time: its curve lies beside the raw one in the
// CSV and the plot, and the summary calls it biased whatever its error does (a filter converges
// to another image than the reference), as it does a clamp. Nothing here is about how good the
// filter is: only that what is measured is the denoised image.
TEST(Converge, ADenoisedConfigurationIsMeasuredBesideTheRawOneAndReportedBiased) {
    testing::ScratchFiles files("converge_denoise");
    const fs::path out = files.directory() / "out";
    testing::CommandResult result = testing::runCommand(
        std::string(PTVIEW_BINARY) + " converge " + testing::shellQuoted(PTVIEW_ASSETS_DIR "/scenes/cornell.json") +
        " --out " + testing::shellQuoted(out.string()) +
        " --size 24x24 --reference-spp 1024 --max-spp 16 --time-budget 60 --configs full/sobol/4,full/sobol/4/denoise");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    std::map<std::string, std::vector<Row>> rows = readCsv(out / "convergence.csv");
    ASSERT_EQ(rows.size(), 2u);
    const std::vector<Row>& raw = rows["full/sobol/4"];
    const std::vector<Row>& denoised = rows["full/sobol/4/denoise"];
    ASSERT_EQ(raw.size(), 5u) << "checkpoints at 1, 2, 4, 8, 16 spp";
    ASSERT_EQ(denoised.size(), raw.size());
    for (std::size_t i = 0; i < raw.size(); ++i) {
        EXPECT_EQ(denoised[i].spp, raw[i].spp);
        EXPECT_TRUE(std::isfinite(denoised[i].relativeMse) && denoised[i].relativeMse > 0.0) << denoised[i].spp << " spp";
        EXPECT_GT(denoised[i].seconds, 0.0);
        // Same settings and seed, so the same samples: a different error is the filter's doing.
        EXPECT_NE(denoised[i].relativeMse, raw[i].relativeMse) << denoised[i].spp << " spp: the raw mean was measured";
        if (i > 0) {
            EXPECT_GT(denoised[i].seconds, denoised[i - 1].seconds) << "the time axis accumulates";
        }
    }
    std::string summary = testing::readFileBytes(out / "summary.md");
    std::istringstream lines(summary);
    bool found = false;
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("| full/sobol/4/denoise |", 0) == 0) {
            found = true;
            EXPECT_NE(line.find("**biased**"), std::string::npos) << line;
            EXPECT_NE(line.find("denoised"), std::string::npos) << line;
        } else if (line.rfind("| full/sobol/4 |", 0) == 0) {
            EXPECT_EQ(line.find("biased"), std::string::npos) << line;
        }
    EXPECT_TRUE(found) << summary;
    EXPECT_EQ(summary.find("Most efficient configuration that converges steadily: **full/sobol/4/denoise**"), std::string::npos)
        << summary;
    EXPECT_NE(result.output.find("full/sobol/4/denoise: 1 spp"), std::string::npos) << result.output;
    EXPECT_GT(fs::file_size(out / "convergence.png"), 1000u) << result.output;
    EXPECT_EQ(result.output.find("warning"), std::string::npos) << result.output;
}

// --all-features was accepted and ignored: the runs used the program specialized to the scene. The
// summary says what the runs were compiled for, as the tracer has it; the empty Cornell box has no
// mesh, the uber-shader has the mesh code.
TEST(Converge, AllFeaturesCompilesEveryFeature) {
    testing::ScratchFiles files("converge_program");
    const fs::path dir = files.write("unused", "").parent_path();
    auto summaryOf = [&](const std::string& name, const std::string& flags) {
        const fs::path out = dir / name;
        testing::CommandResult result = testing::runCommand(
            std::string(PTVIEW_BINARY) + " converge " + testing::shellQuoted(PTVIEW_ASSETS_DIR "/scenes/cornell.json") +
            " --out " + testing::shellQuoted(out.string()) +
            " --size 16x16 --reference-spp 2 --max-spp 2 --configs naive/random/1 --backend fragment" + flags);
        EXPECT_EQ(result.exitCode, 0) << result.output;
        return testing::readFileBytes(out / "summary.md");
    };
    const std::string specialized = summaryOf("specialized", "");
    EXPECT_NE(specialized.find("Program: the fragment backend, compiled for materials: diffuse"), std::string::npos)
        << specialized;
    EXPECT_NE(specialized.find("; meshes: no;"), std::string::npos) << specialized;
    const std::string uber = summaryOf("uber", " --all-features");
    EXPECT_NE(uber.find("; meshes: yes (two-level BVH);"), std::string::npos) << uber;
    EXPECT_NE(uber.find("; environment: map;"), std::string::npos) << uber;
}

// A reference with a NaN pixel gave a CSV of nan and a summary claiming every error target reached
// at the first checkpoint. It is refused before any rendering, naming the file and the pixel.
TEST(Converge, ReferenceWithANaNPixelIsRefused) {
    testing::ScratchFiles files("converge_nan");
    ImageRgbF image;
    image.width = 8, image.height = 8;
    image.rgb.assign(8 * 8 * 3, 0.25f);
    image.rgb[(2 * 8 + 3) * 3] = std::numeric_limits<float>::quiet_NaN();
    const fs::path reference = files.write("nan.pfm", "");
    writePfm(reference, image);
    const fs::path out = reference.parent_path() / "out";
    testing::CommandResult result = testing::runCommand(
        std::string(PTVIEW_BINARY) + " converge " + testing::shellQuoted(PTVIEW_ASSETS_DIR "/scenes/cornell.json") +
        " --out " + testing::shellQuoted(out.string()) + " --reference " + testing::shellQuoted(reference.string()) +
        " --max-spp 2 --configs naive/random/1");
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find(reference.string() + ": pixel (3, 2) is NaN (1 of 64 pixels"), std::string::npos)
        << result.output;
    EXPECT_FALSE(fs::exists(out / "summary.md"));
}

// With no finite pixel to compare, the error is NaN, never the 0 that read as a perfect match and
// as every target reached.
TEST(Converge, AnImageWithNoFinitePixelHasNoError) {
    ImageRgbF reference;
    reference.width = 2, reference.height = 1;
    reference.rgb.assign(6, 0.5f);
    ImageRgbF image = reference;
    image.rgb.assign(6, std::numeric_limits<float>::quiet_NaN());
    const ErrorMetrics error = compareToReference(image, reference);
    EXPECT_TRUE(std::isnan(error.relativeMse));
    EXPECT_TRUE(std::isnan(error.rmse));
    EXPECT_EQ(error.nonFiniteShare, 1.0);
    image.rgb[0] = image.rgb[1] = image.rgb[2] = 0.5f;
    EXPECT_EQ(compareToReference(image, reference).relativeMse, 0.0);
}

// Before: the plot command was pasted into std::system, so a directory name could run code, and a
// legitimate `it's/` got no plot with a warning that blamed matplotlib. The helper now runs with
// an argument vector: the name below, quote and semicolons included, is only a name.
TEST(Converge, OutputDirectoryNamesAreNeverRunAsCode) {
    fs::path base = fs::temp_directory_path() / ("ptview_converge_quote_" + std::to_string(::getpid()));
    fs::remove_all(base);
    fs::create_directories(base);
    const fs::path pwned = base / "PWNED";
    const fs::path out = base / ("it's'; touch '" + pwned.string() + "'; echo '");
    testing::CommandResult result = testing::runCommand(
        std::string(PTVIEW_BINARY) + " converge " + testing::shellQuoted(PTVIEW_ASSETS_DIR "/scenes/cornell.json") +
        " --out \"" + out.string() + "\" --size 8x8 --reference-spp 4 --max-spp 2 --configs naive/random/1");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_FALSE(fs::exists(pwned)) << "the directory's name ran as a shell command";
    EXPECT_TRUE(fs::exists(out / "convergence.csv"));
    EXPECT_GT(fs::file_size(out / "convergence.png"), 1000u) << result.output;
    EXPECT_EQ(result.output.find("warning"), std::string::npos) << result.output;
    fs::remove_all(base);
}

// Before: an existing file as the output directory was found only after the reference and all
// the runs were rendered (exit 1).
TEST(Converge, OutputDirectoryThatIsAFileIsRefusedBeforeRendering) {
    const fs::path file = fs::temp_directory_path() / ("ptview_converge_file_" + std::to_string(::getpid()));
    std::ofstream(file) << "not a directory";
    testing::CommandResult result = testing::runCommand(
        std::string(PTVIEW_BINARY) + " converge " + testing::shellQuoted(PTVIEW_ASSETS_DIR "/scenes/cornell.json") +
        " --out " + testing::shellQuoted(file.string()) + " --size 8x8 --configs naive/random/1");
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find(file.string() + ": exists and is not a directory"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("rendering the reference"), std::string::npos) << result.output;
    EXPECT_EQ(testing::readFileBytes(file), "not a directory");
    fs::remove(file);
}

} // namespace
} // namespace ptview
