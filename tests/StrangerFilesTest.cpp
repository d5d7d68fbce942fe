// Images from strangers (issue 33, docs/robustness.md "Files from strangers"), through the real
// binary: the scene a PNG carries reads only inside the image's folder (or where the user allowed),
// sets no save target, and its settings are bounded as the command line bounds them; `render
// --from` applies or refuses each other option, never ignores it.
#include <ptview/io/ImageIO.h>
#include <ptview/io/PngText.h>
#include "RunCommand.h"
#include "ScriptStatus.h"
#include "TestFiles.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <fstream>
#include <string>
#include <vector>

namespace ptview {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const std::string kBinary = PTVIEW_BINARY;
const std::string kCornell = PTVIEW_ASSETS_DIR "/scenes/cornell.json";

testing::CommandResult run(const std::string& arguments) {
    return testing::runCommand(kBinary + " " + arguments);
}

std::string quoted(const fs::path& path) {
    return testing::shellQuoted(path.string());
}

class StrangerFiles : public ::testing::Test {
protected:
    void SetUp() override {
        fs::create_directories(dir_ / "downloads");
        fs::create_directories(dir_ / "private");
    }

    // A PNG ptview wrote of the Cornell box (16x16, 1 spp) in downloads/, as a stranger would send it.
    fs::path sentImage() {
        const fs::path image = dir_ / "downloads" / "shot.png";
        const testing::CommandResult render =
            run("render " + testing::shellQuoted(kCornell) + " --out " + quoted(image) + " --spp 4 --size 16x16 --backend fragment");
        EXPECT_EQ(render.exitCode, 0) << render.output;
        return image;
    }

    // The same image with its metadata changed by `edit`, written as downloads/NAME (a new PNG of
    // the same metadata, as a sender could make with any tool).
    fs::path editedImage(const fs::path& image, const std::string& name, const std::function<void(ImageMetadata&)>& edit) {
        ImageMetadata metadata = readPngTextFile(image);
        edit(metadata);
        ImageRgba8 pixels;
        pixels.width = pixels.height = 4;
        pixels.rgba.assign(4 * 4 * 4, 128);
        const fs::path out = dir_ / "downloads" / name;
        writePng(out, pixels, metadata);
        return out;
    }

    // The image whose scene's red material takes its colour from `texturePath`, as written in the scene.
    fs::path imageWithTexture(const fs::path& image, const std::string& name, const std::string& texturePath) {
        return editedImage(image, name, [&](ImageMetadata& metadata) {
            Json scene = Json::parse(*metadata.find("ptview.scene"));
            scene["materials"]["red"]["albedo"] = texturePath;
            metadata.set("ptview.scene", scene.dump(2));
        });
    }

    // A small PNG texture at `path`.
    static void writeTexture(const fs::path& path) {
        ImageRgba8 texels;
        texels.width = texels.height = 2;
        texels.rgba.assign(2 * 2 * 4, 200);
        writePng(path, texels);
    }

    testing::ScratchFiles scratch_{"stranger"};
    const fs::path dir_ = scratch_.directory();
};

// The scene in a PNG may name textures anywhere; only those in the image's folder tree, or in a
// folder allowed with --allow-dir, are read. The refusal names the image, the place in its scene
// and the file, and writes nothing; no byte of the refused file is read (it is a PNG that would
// decode).
TEST_F(StrangerFiles, ASentImagesSceneReadsOnlyInsideTheImagesFolderUnlessAllowed) {
    const fs::path image = sentImage();
    writeTexture(dir_ / "private" / "secret.png");
    writeTexture(dir_ / "downloads" / "beside.png");
    const fs::path out = dir_ / "out.png";
    const fs::path absolute = imageWithTexture(image, "absolute.png", (dir_ / "private" / "secret.png").string());
    // "../" out of the image's folder, from a scene file said to be beside the image.
    const fs::path climbing = editedImage(imageWithTexture(image, "climbing.png", "../private/secret.png"), "climbing.png",
                                          [&](ImageMetadata& metadata) {
                                              metadata.set("ptview.scene_file", (dir_ / "downloads" / "scene.json").string());
                                          });
    // Relative paths in ptview.scene are relative to ptview.scene_file's folder, which the sender chose.
    const fs::path viaSceneFile = editedImage(climbing, "via_scene_file.png", [&](ImageMetadata& metadata) {
        metadata.set("ptview.scene_file", (dir_ / "private" / "scene.json").string());
        Json scene = Json::parse(*metadata.find("ptview.scene"));
        scene["materials"]["red"]["albedo"] = "secret.png";
        metadata.set("ptview.scene", scene.dump(2));
    });
    fs::create_directory_symlink(dir_ / "private", dir_ / "downloads" / "link");
    const fs::path throughLink = imageWithTexture(image, "link.png", (dir_ / "downloads" / "link" / "secret.png").string());
    for (const fs::path& hostile : {absolute, climbing, viaSceneFile, throughLink}) {
        const testing::CommandResult result = run("render --from " + quoted(hostile) + " --out " + quoted(out));
        EXPECT_EQ(result.exitCode, 2) << hostile << "\n" << result.output;
        EXPECT_NE(result.output.find(hostile.string() + ": the scene it was rendered from"), std::string::npos) << result.output;
        EXPECT_NE(result.output.find("/materials/red/albedo"), std::string::npos) << "the place in its scene: " << result.output;
        EXPECT_NE(result.output.find((dir_ / "private" / "secret.png").string() + " is outside the folder of " +
                                     hostile.filename().string()),
                  std::string::npos)
            << result.output;
        EXPECT_FALSE(fs::exists(out)) << hostile;
    }
    // The user's word: --allow-dir reads that folder too.
    const testing::CommandResult allowed =
        run("render --from " + quoted(absolute) + " --out " + quoted(out) + " --allow-dir " + quoted(dir_ / "private"));
    EXPECT_EQ(allowed.exitCode, 0) << allowed.output;
    // Inside the image's own folder nothing needs allowing.
    const fs::path beside = imageWithTexture(image, "beside_texture.png", (dir_ / "downloads" / "beside.png").string());
    const testing::CommandResult inside = run("render --from " + quoted(beside) + " --out " + quoted(out));
    EXPECT_EQ(inside.exitCode, 0) << inside.output;
}

// A scene file the user names is the user's own: it reads what it names, wherever that is.
TEST_F(StrangerFiles, AScenesOwnFileReadsWhatItNames) {
    writeTexture(dir_ / "private" / "mine.png");
    Json scene = Json::parse(testing::readFileBytes(kCornell));
    scene["materials"]["red"]["albedo"] = (dir_ / "private" / "mine.png").string();
    std::ofstream(dir_ / "downloads" / "scene.json") << scene.dump(2);
    const testing::CommandResult result =
        run("render " + quoted(dir_ / "downloads" / "scene.json") + " --out " + quoted(dir_ / "out.png") + " --spp 1 --size 8x8");
    EXPECT_EQ(result.exitCode, 0) << result.output;
}

// Each setting an image carries is checked against the range the command line gives it
// (SettingRanges.h): a value outside is refused naming the file and the setting, never rendered.
TEST_F(StrangerFiles, SettingsFromAnImageAreBoundedAsTheCommandLineBoundsThem) {
    const fs::path image = sentImage();
    struct Case {
        const char* key;
        Json value;
    };
    const std::vector<Case> cases = {
        {"spp", 0}, {"spp", -1}, {"spp", 16777217}, {"spp", 2.5}, {"max_depth", -1}, {"max_depth", 100000},
        {"seed", -1}, {"seed", 4294967296.0}, {"exposure_stops", 1000}, {"radiance_clamp", 0}, {"radiance_clamp", -1},
        {"radiance_clamp", 1e-45}, {"radiance_clamp", 1e39}, {"width", 16.7}, {"width", 0}, {"height", 0},
        {"height", 16385}, {"sample_budget", 0}, {"spp", "4"},
    };
    int n = 0;
    for (const Case& c : cases) {
        const fs::path edited = editedImage(image, "case" + std::to_string(n++) + ".png", [&](ImageMetadata& metadata) {
            Json settings = Json::parse(*metadata.find("ptview.settings"));
            settings[c.key] = c.value;
            metadata.set("ptview.settings", settings.dump(2));
        });
        const testing::CommandResult info = run("info " + quoted(edited));
        EXPECT_EQ(info.exitCode, 2) << c.key << " " << c.value << "\n" << info.output;
        EXPECT_NE(info.output.find(edited.string() + ": settings \"" + c.key + "\""), std::string::npos) << info.output;
    }
    // The same check stops a render before it starts, and a window before it opens.
    const fs::path zeroSpp = dir_ / "downloads" / "case0.png";
    const testing::CommandResult render = run("render --from " + quoted(zeroSpp) + " --out " + quoted(dir_ / "out.png"));
    EXPECT_EQ(render.exitCode, 2) << render.output;
    EXPECT_FALSE(fs::exists(dir_ / "out.png"));
    // The bounds themselves are accepted: spp 1 and a clamp of 1e9 render.
    const fs::path atBounds = editedImage(image, "bounds.png", [](ImageMetadata& metadata) {
        Json settings = Json::parse(*metadata.find("ptview.settings"));
        settings["spp"] = 1;
        settings["radiance_clamp"] = 1e9;
        settings["seed"] = 4294967295u;
        metadata.set("ptview.settings", settings.dump(2));
    });
    const testing::CommandResult bounds = run("render --from " + quoted(atBounds) + " --out " + quoted(dir_ / "out.png"));
    EXPECT_EQ(bounds.exitCode, 0) << bounds.output;
}

// With --from, the options that apply do (and --spp is recorded in the new file), and every other
// one is refused with exit code 2 instead of being ignored.
TEST_F(StrangerFiles, RenderFromAppliesOrRefusesEachOtherOption) {
    const fs::path image = sentImage();
    const fs::path out = dir_ / "out.png";
    for (const std::string option : {"--integrator naive", "--size 8x8", "--depth 2", "--seed 3", "--exposure 1",
                                     "--aperture-radius 0.1", "--focus-distance 2", "--backend compute", "--all-features",
                                     "--clamp 5", "--sampler random", "--view albedo", "--tone-mapper aces",
                                     "--display-transfer gamma-2.2", "--ocio-view Filmic"}) {
        const testing::CommandResult result = run("render --from " + quoted(image) + " --out " + quoted(out) + " " + option);
        EXPECT_EQ(result.exitCode, 2) << option << "\n" << result.output;
        EXPECT_NE(result.output.find(option.substr(0, option.find(' ')) + " cannot go with --from"), std::string::npos)
            << result.output;
        EXPECT_FALSE(fs::exists(out)) << option;
    }
    // --spp applies and is what the new file records.
    const testing::CommandResult more = run("render --from " + quoted(image) + " --out " + quoted(out) + " --spp 8");
    ASSERT_EQ(more.exitCode, 0) << more.output;
    EXPECT_EQ(Json::parse(*readPngTextFile(out).find("ptview.settings"))["spp"], 8);
    // --time applies: a limit of 0 s stops after the first pass, short of the recorded 4 spp.
    const fs::path timed = dir_ / "timed.png";
    const testing::CommandResult time = run("render --from " + quoted(image) + " --out " + quoted(timed) + " --time 0 --spp 1024");
    ASSERT_EQ(time.exitCode, 0) << time.output;
    EXPECT_NE(time.output.find("--time 0 s passed"), std::string::npos) << time.output;
    EXPECT_LT(Json::parse(*readPngTextFile(timed).find("ptview.settings"))["spp"].get<int>(), 1024);
}

// The options that a file's settings are bounded by behave alike on the command line: the clamp's
// denormal and overflowing values, --exr-type without an EXR, and --view-from beyond the scene's bounds.
TEST_F(StrangerFiles, CommandLineBoundsMatchTheFileBounds) {
    const std::string render = "render " + testing::shellQuoted(kCornell) + " --spp 1 --size 8x8 --out ";
    for (const std::string& arguments :
         {render + quoted(dir_ / "a.png") + " --clamp 1e-45", render + quoted(dir_ / "a.png") + " --clamp 1e39",
          render + quoted(dir_ / "a.png") + " --exr-type half", render + quoted(dir_ / "a.png") + " --exr-type float",
          render + quoted(dir_ / "a.png") + " --seed -1", render + quoted(dir_ / "a.png") + " --seed 4294967296",
          "paths " + testing::shellQuoted(kCornell) + " --pixel 1 1 --out " + quoted(dir_ / "p.json") + " --image " +
              quoted(dir_ / "p.png") + " --view-from 1e30 0 0"}) {
        const testing::CommandResult result = run(arguments);
        EXPECT_EQ(result.exitCode, 2) << arguments << "\n" << result.output;
    }
    EXPECT_FALSE(fs::exists(dir_ / "a.png"));
    EXPECT_FALSE(fs::exists(dir_ / "p.json"));
    const testing::CommandResult exr = run(render + quoted(dir_ / "a.exr") + " --exr-type half --clamp 1e9");
    EXPECT_EQ(exr.exitCode, 0) << exr.output;
}

// The hostile PNG of the issue: its ptview.scene_file names the user's notes. Opening it in the
// viewer, editing a material, then Escape and S (save in the unsaved-edits question) must not
// touch the notes: an image's scene has no save target, so Save asks for a name instead.
TEST_F(StrangerFiles, ASentImagesSceneFileIsNeverASaveTarget) {
    const fs::path image = sentImage();
    const fs::path notes = dir_ / "private" / "notes.txt";
    std::ofstream(notes) << "my notes\n";
    const fs::path hostile = editedImage(image, "hostile.png", [&](ImageMetadata& metadata) {
        metadata.set("ptview.scene_file", notes.string());
    });
    std::ofstream(dir_ / "downloads" / "script.txt") << R"(resolution-scale 0.125
target-spp 1
set-material red.color 0 0 1
frames 2
status
wait-seconds 3
status
wait-seconds 3
status
wait-seconds 60
)";
    const testing::CommandResult result = testing::runCommand(
        "cd " + quoted(dir_ / "downloads") + " && " + testing::xvfbRun("1600x1000x24") + "bash " +
        PTVIEW_TEST_SCRIPT_DIR + "/window_steps.sh " + kBinary + " hostile.png Escape s d");
    EXPECT_EQ(result.exitCode, 0) << result.output;
    const std::vector<std::string> status = testing::statusLines(result.output);
    ASSERT_GE(status.size(), 3u) << result.output;
    EXPECT_EQ(testing::field(status[0], "edits"), "materials") << result.output;
    EXPECT_EQ(testing::field(status[0], "save-target"), "\"\"") << "the image's scene file is no target";
    EXPECT_EQ(testing::field(status[1], "prompt"), "quit") << "Escape asks";
    EXPECT_EQ(testing::field(status[2], "prompt"), "quit") << "S found no file to save to, and still asks";
    EXPECT_EQ(testing::readFileBytes(notes), "my notes\n");
    EXPECT_NE(result.output.find("exited after d"), std::string::npos) << result.output;
}

// The viewer asks before reading a folder outside a sent image's own, naming the file: Enter
// allows it (and the scene opens), Escape refuses it (exit code 2, no window left).
TEST_F(StrangerFiles, TheViewerAsksBeforeReadingAFolderOutsideTheImagesAndNamesTheFile) {
    const fs::path image = sentImage();
    writeTexture(dir_ / "private" / "secret.png");
    const fs::path hostile = imageWithTexture(image, "outside.png", (dir_ / "private" / "secret.png").string());
    for (const std::string key : {"Return", "Escape"}) {
        const testing::CommandResult result = testing::runCommand(
            "cd " + quoted(dir_ / "downloads") + " && " + testing::xvfbRun("1600x1000x24") + "bash " +
            PTVIEW_TEST_SCRIPT_DIR + "/window_steps.sh " + kBinary + " outside.png --prompt " + key);
        EXPECT_NE(result.output.find("asking in the window whether to read " + (dir_ / "private").string()),
                  std::string::npos)
            << result.output;
        EXPECT_NE(result.output.find((dir_ / "private" / "secret.png").string() + " is outside the folder of outside.png"),
                  std::string::npos)
            << "the refused file is named: " << result.output;
        if (key == "Return") {
            EXPECT_EQ(result.exitCode, 0) << result.output;
            EXPECT_TRUE(fs::exists(dir_ / "downloads" / "window.png")) << result.output;
        } else {
            EXPECT_EQ(result.exitCode, 2) << result.output;
            EXPECT_NE(result.output.find("not allowed: " + (dir_ / "private").string()), std::string::npos) << result.output;
        }
        fs::remove(dir_ / "downloads" / "window.png");
    }
}

} // namespace
} // namespace ptview
