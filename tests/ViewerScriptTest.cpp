#include <ptview/model/ViewerScript.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace ptview;

namespace {

ViewerScript parse(const std::string& text) { return parseViewerScript(text, "s.txt"); }

// The ScriptError message for text; fails the test when text parses.
std::string errorOf(const std::string& text) {
    try {
        parse(text);
    } catch (const ScriptError& e) {
        return e.what();
    }
    ADD_FAILURE() << "parsed without an error:\n" << text;
    return "";
}

std::vector<std::string> verbsOf(const ViewerScript& script) {
    std::vector<std::string> verbs;
    for (const ScriptCommand& command : script.commands) verbs.push_back(command.verb);
    return verbs;
}

// The first word of each command line of the reference (field lines are indented).
std::set<std::string> referenceVerbs() {
    std::set<std::string> verbs;
    std::istringstream lines(viewerScriptReference());
    for (std::string line; std::getline(lines, line);)
        if (!line.empty() && line[0] != ' ') verbs.insert(line.substr(0, line.find(' ')));
    return verbs;
}

const char* kEveryVerb = R"(integrator mis
sampler sobol
depth 12
seed 4294967295
exposure -1.5
tone-mapper aces
resolution-scale 0.5
samples-per-frame auto
samples-per-frame 4
pause
resume
target-spp 0
set-material glass.ior 1.5
set-light key.intensity 10 10 8
environment assets/env/sky map.hdr
environment none
environment-intensity 2
environment-rotation -90
environment-color 0.1 0.2 0.3
camera-orbit 30 -10
camera-pan 0.1 -0.05
camera-zoom 2
camera-fov 45
camera-reset
load-scene assets/scenes/cornell.json
reload
compare on
compare-integrator full
compare-sampler stratified
compare-depth 3
divider 0.25
frames 10
wait-spp 64
screenshot out/render.pfm
screenshot-window out/window.png
save-screenshots
save-scene out/edited.json
copy-file a.json b.json
wait-reload
status
quit
open-panel materials
open-material gold
reference ref.pfm
wait-seconds 0.5
clamp 10
clamp off
camera-aperture 0.05
camera-focus 3.5
camera-focus-at 0.25 0.75
light-paths exactly
light-path-bounces 2
pin-pixel 3 48
unpin-pixel
save-pixel out/pixel.json
path-count 8
trace-paths
save-paths out/paths.json
denoise on
denoise-strength 6
denoise-iterations 4
denoise-algorithm regression
wait-denoised
compare-sides raw-denoised
compare-denoise on
pop-out paths-table on
ui-scale 1.5
high-contrast on
view error-map
error-range 0.001 1
difference-range 0.25
load-compare-image out/other image.exr
zoom 4
zoom fit
pan 12 -3.5
compare-sides image-view
display-transfer gamma-2.2
undo
redo
target-error 0.02
target-error off
ocio-config looks/config.ocio
ocio-display sRGB
ocio-view Filmic Log
)";

} // namespace

TEST(ViewerScript, EveryVerbParsesWithItsArgumentsAndLine) {
    ViewerScript script = parse(kEveryVerb);
    ASSERT_EQ(script.commands.size(), 84u);
    EXPECT_EQ(script.path, "s.txt");

    // The script must exercise every command the table has, so a new verb cannot go untested.
    std::vector<std::string> verbs = verbsOf(script);
    EXPECT_EQ(std::set<std::string>(verbs.begin(), verbs.end()), referenceVerbs());

    for (std::size_t i = 0; i < script.commands.size(); ++i) EXPECT_EQ(script.commands[i].line, int(i) + 1);
    // An OpenColorIO view's name is the rest of the line, spaces included.
    auto ocioView = std::find_if(script.commands.begin(), script.commands.end(),
                                 [](const ScriptCommand& command) { return command.verb == "ocio-view"; });
    ASSERT_NE(ocioView, script.commands.end());
    EXPECT_EQ(ocioView->words, std::vector<std::string>{"Filmic Log"});

    const auto& c = script.commands;
    EXPECT_EQ(c[0].verb, "integrator");
    EXPECT_EQ(c[0].words, std::vector<std::string>{"mis"});
    EXPECT_EQ(c[2].integer(0), 12);
    EXPECT_EQ(c[3].unsignedInteger(0), 4294967295u);
    EXPECT_FLOAT_EQ(c[4].number(0), -1.5f);
    EXPECT_TRUE(c[7].isWord(0, "auto"));
    EXPECT_FALSE(c[8].isWord(0, "auto"));
    EXPECT_EQ(c[8].integer(0), 4);
    EXPECT_TRUE(c[9].words.empty());

    EXPECT_EQ(c[12].target, "glass");
    EXPECT_EQ(c[12].field, "ior");
    EXPECT_EQ(c[12].words, std::vector<std::string>{"1.5"});
    EXPECT_EQ(c[13].target, "key");
    EXPECT_EQ(c[13].field, "intensity");
    EXPECT_EQ(c[13].vec3(0), glm::vec3(10.0f, 10.0f, 8.0f));

    // A path is the rest of the line, spaces included.
    EXPECT_EQ(c[14].words, std::vector<std::string>{"assets/env/sky map.hdr"});
    EXPECT_TRUE(c[15].isWord(0, "none"));
    EXPECT_EQ(c[18].vec3(0), glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_FLOAT_EQ(c[19].number(1), -10.0f);
    EXPECT_EQ(c[26].words, std::vector<std::string>{"on"});
    EXPECT_EQ(c[27].words, std::vector<std::string>{"full"});
    EXPECT_EQ(c[33].words, std::vector<std::string>{"out/render.pfm"});
    EXPECT_EQ(c[37].words, (std::vector<std::string>{"a.json", "b.json"}));
    EXPECT_EQ(c[40].verb, "quit");
    EXPECT_EQ(c[50].words, std::vector<std::string>{"exactly"});
    EXPECT_EQ(c[51].integer(0), 2);
    EXPECT_EQ(c[52].integer(0), 3);
    EXPECT_EQ(c[52].integer(1), 48);
    EXPECT_EQ(c[54].words, std::vector<std::string>{"out/pixel.json"});
    EXPECT_EQ(c[55].integer(0), 8);
    EXPECT_EQ(c[57].words, std::vector<std::string>{"out/paths.json"});
}

TEST(ViewerScript, CommentsAndBlankLinesAreSkippedButCountedAsLines) {
    ViewerScript script = parse("# a demo\n"
                                "\n"
                                "   \t\n"
                                "integrator full   # global illumination\n"
                                "  # indented comment\n"
                                "screenshot  out dir/my shot.png   # trailing comment\r\n"
                                "quit");
    ASSERT_EQ(script.commands.size(), 3u);
    EXPECT_EQ(script.commands[0].line, 4);
    EXPECT_EQ(script.commands[0].words, std::vector<std::string>{"full"});
    EXPECT_EQ(script.commands[1].line, 6);
    EXPECT_EQ(script.commands[1].words, std::vector<std::string>{"out dir/my shot.png"});
    EXPECT_EQ(script.commands[2].line, 7); // no final newline
    EXPECT_TRUE(parse("# only comments\n\n").commands.empty());
}

// A script saved with a UTF-8 byte-order mark failed as unknown command "\xEF\xBB\xBFstatus". The mark
// is skipped at the start of the file only; elsewhere it is part of a word.
TEST(ViewerScript, AByteOrderMarkAtTheStartIsSkipped) {
    ViewerScript script = parse("\xEF\xBB\xBFstatus\nquit\n");
    ASSERT_EQ(script.commands.size(), 2u);
    EXPECT_EQ(script.commands[0].verb, "status");
    EXPECT_EQ(script.commands[0].line, 1);
    EXPECT_EQ(parse("\xEF\xBB\xBF# a comment\ndepth 3\n").commands.at(0).line, 2);
    EXPECT_EQ(errorOf("status\n\xEF\xBB\xBFquit\n").rfind("s.txt:2: unknown command", 0), 0u);
}

TEST(ViewerScript, MaterialNameWithDotsSplitsAtTheLastDot) {
    ViewerScript script = parse("set-material glass.001.ior 1.45\nset-material light.bulb.emission 5 4 3\n");
    EXPECT_EQ(script.commands[0].target, "glass.001");
    EXPECT_EQ(script.commands[0].field, "ior");
    EXPECT_FLOAT_EQ(script.commands[0].number(0), 1.45f);
    EXPECT_EQ(script.commands[1].target, "light.bulb");
    EXPECT_EQ(script.commands[1].field, "emission");
    EXPECT_EQ(script.commands[1].vec3(0), glm::vec3(5.0f, 4.0f, 3.0f));
}

TEST(ViewerScript, UnknownCommandNamesItAndSuggestsTheNearest) {
    EXPECT_EQ(errorOf("depth 3\nintegrater mis\n"), "s.txt:2: unknown command \"integrater\" (did you mean \"integrator\"?)");
    EXPECT_EQ(errorOf("frobnicate\n"), "s.txt:1: unknown command \"frobnicate\" (see docs/viewer-script.md)");
}

TEST(ViewerScript, UnknownNamesListTheValidOnes) {
    EXPECT_EQ(errorOf("# x\n\nintegrator foo\n"),
              "s.txt:3: integrator: unknown integrator \"foo\" (valid: naive, direct, mis, full)");
    EXPECT_EQ(errorOf("sampler halton"),
              "s.txt:1: sampler: unknown sampler \"halton\" (valid: random, grid, stratified, sobol)");
    EXPECT_EQ(errorOf("tone-mapper filmic"),
              "s.txt:1: tone-mapper: unknown tone mapper \"filmic\" (valid: reinhard, aces, clamp, agx, ocio)");
    EXPECT_EQ(errorOf("compare yes"), "s.txt:1: compare: unknown value \"yes\" (valid: on, off)");
    std::string type = errorOf("set-material m.type velvet");
    EXPECT_NE(type.find("s.txt:1: set-material: type: unknown material type \"velvet\" (valid: diffuse, emitter,"),
              std::string::npos)
        << type;
}

TEST(ViewerScript, NumbersParseStrictly) {
    EXPECT_EQ(errorOf("exposure 1.5x"), "s.txt:1: exposure: expected a number for F, got \"1.5x\"");
    EXPECT_EQ(errorOf("depth 1.5"), "s.txt:1: depth: expected an integer for N, got \"1.5\"");
    EXPECT_EQ(errorOf("depth 1e3"), "s.txt:1: depth: expected an integer for N, got \"1e3\"");
    EXPECT_EQ(errorOf("camera-fov 0x10"), "s.txt:1: camera-fov: expected a number for DEG, got \"0x10\"");
    EXPECT_EQ(errorOf("samples-per-frame fast"),
              "s.txt:1: samples-per-frame: expected an integer or \"auto\" for N, got \"fast\"");
    // A leading '+' is allowed, and so is a tiny value (it rounds to 0).
    EXPECT_FLOAT_EQ(parse("camera-orbit +15 -5").commands[0].number(0), 15.0f);
    EXPECT_EQ(parse("environment-rotation 1e-60").commands[0].number(0), 0.0f);
}

// A documented bound no float holds (the clamp's 1e-6) stands for the float nearest it, so the
// bound itself can be typed; the next float below is still out of range.
TEST(ViewerScript, ABoundNoFloatHoldsCanBeTyped) {
    EXPECT_EQ(parse("clamp 1e-06").commands[0].number(0), 1e-6f);
    EXPECT_EQ(errorOf("clamp 9.9e-07"), "s.txt:1: clamp: VALUE must be in [1e-06, 1000000000], got 9.9e-07");
}

TEST(ViewerScript, NonFiniteNumbersAreRejected) {
    EXPECT_EQ(errorOf("exposure nan"), "s.txt:1: exposure: F must be a finite number, got \"nan\"");
    EXPECT_EQ(errorOf("environment-rotation -inf"),
              "s.txt:1: environment-rotation: DEG must be a finite number, got \"-inf\"");
    EXPECT_EQ(errorOf("camera-orbit 0 1e999"), "s.txt:1: camera-orbit: PITCH must be a finite number, got \"1e999\"");
    EXPECT_EQ(errorOf("camera-pan 1e39 0"), "s.txt:1: camera-pan: RIGHT is too large for a float, got \"1e39\"");
}

TEST(ViewerScript, OutOfRangeValuesSayTheRange) {
    EXPECT_EQ(errorOf("depth 2000"), "s.txt:1: depth: N must be in 0..1024, got 2000");
    EXPECT_EQ(errorOf("depth 99999999999999999999999"),
              "s.txt:1: depth: N must be in 0..1024, got 99999999999999999999999");
    EXPECT_EQ(errorOf("seed -1"), "s.txt:1: seed: N must be in 0..4294967295, got -1");
    EXPECT_EQ(errorOf("seed 4294967296"), "s.txt:1: seed: N must be in 0..4294967295, got 4294967296");
    EXPECT_EQ(errorOf("exposure 21"), "s.txt:1: exposure: F must be in [-20, 20], got 21");
    EXPECT_EQ(errorOf("resolution-scale 0.1"), "s.txt:1: resolution-scale: F must be in [0.125, 2], got 0.1");
    EXPECT_EQ(errorOf("camera-zoom 0"), "s.txt:1: camera-zoom: FACTOR must be > 0, got 0");
    EXPECT_EQ(errorOf("frames 0"), "s.txt:1: frames: N must be >= 1, got 0");
    EXPECT_EQ(errorOf("target-spp -4"), "s.txt:1: target-spp: N must be >= 0, got -4");
    EXPECT_EQ(errorOf("target-error 0"), "s.txt:1: target-error: E must be in (0, 1], got 0");
    EXPECT_EQ(errorOf("target-error 2"), "s.txt:1: target-error: E must be in (0, 1], got 2");
    EXPECT_EQ(errorOf("samples-per-frame 0"), "s.txt:1: samples-per-frame: N must be in 1..1024, got 0");
    EXPECT_EQ(errorOf("divider 1.01"), "s.txt:1: divider: F must be in [0, 1], got 1.01");
    EXPECT_EQ(errorOf("environment-color 0 -1 0"), "s.txt:1: environment-color: G must be in [0, 1000000000], got -1");
    EXPECT_EQ(errorOf("set-material m.color 0.5 1.5 0"), "s.txt:1: set-material: color: G must be in [0, 1], got 1.5");
    EXPECT_EQ(errorOf("set-material m.ior 0.9"), "s.txt:1: set-material: ior: IOR must be in [1, 4], got 0.9");
    EXPECT_EQ(errorOf("set-light l.outer-angle 190"),
              "s.txt:1: set-light: outer-angle: DEG must be in (0, 90], got 190");
    EXPECT_EQ(errorOf("set-light l.direction 0 0 0"), "s.txt:1: set-light: direction: must not be (0, 0, 0)");
    // The bounds themselves are in range.
    EXPECT_EQ(parse("depth 0\ndepth 1024\nresolution-scale 0.125\ncamera-fov 179\n").commands.size(), 4u);
}

// The scene's numbers take the file format's ranges (SceneRanges.h), open ends included: what a
// script sets, Save can write. They disagreed: the script took cone angles in [0, 180].
TEST(ViewerScript, SceneValuesTakeTheFileFormatsRanges) {
    EXPECT_EQ(errorOf("set-light spot.inner-angle 0"), "s.txt:1: set-light: inner-angle: DEG must be in (0, 90], got 0");
    EXPECT_EQ(errorOf("# the cone\n\nset-light spot.outer-angle 120"),
              "s.txt:3: set-light: outer-angle: DEG must be in (0, 90], got 120");
    EXPECT_EQ(errorOf("set-light spot.outer-angle 90.00001"),
              "s.txt:1: set-light: outer-angle: DEG must be in (0, 90], got 90.00001");
    EXPECT_EQ(errorOf("camera-fov 180"), "s.txt:1: camera-fov: DEG must be in (0, 180), got 180");
    EXPECT_EQ(errorOf("set-material m.roughness 1.01"), "s.txt:1: set-material: roughness: R must be in [0, 1], got 1.01");
    EXPECT_EQ(errorOf("set-material m.emission 0 0 -1"), "s.txt:1: set-material: emission: B must be in [0, 1000000000], got -1");
    EXPECT_EQ(errorOf("set-material m.metallic 1.5"), "s.txt:1: set-material: metallic: F must be in [0, 1], got 1.5");
    EXPECT_EQ(errorOf("set-material m.alpha -0.1"), "s.txt:1: set-material: alpha: F must be in [0, 1], got -0.1");
    EXPECT_EQ(errorOf("set-material m.base-color-texture x.txt"),
              "s.txt:1: set-material: base-color-texture: PATH must end in .png or .jpg or .jpeg, got \"x.txt\"");
    EXPECT_EQ(errorOf("set-light spot.intensity -1 0 0"), "s.txt:1: set-light: intensity: R must be in [0, 1000000000], got -1");
    EXPECT_EQ(errorOf("environment-intensity -0.5"), "s.txt:1: environment-intensity: F must be in [0, 1000000000], got -0.5");
    // The range's own bounds, and a fov just inside its open end, are taken.
    EXPECT_EQ(parse("set-light spot.outer-angle 90\nset-light spot.inner-angle 1e-30\ncamera-fov 179.99\n"
                    "set-material m.ior 4\nenvironment-rotation -720\n")
                  .commands.size(),
              5u);
}

TEST(ViewerScript, WrongArgumentCountSaysHowManyWereExpected) {
    EXPECT_EQ(errorOf("depth 3 4"), "s.txt:1: depth: expected 1 argument (depth N), got 2");
    EXPECT_EQ(errorOf("depth"), "s.txt:1: depth: expected 1 argument (depth N), got 0");
    EXPECT_EQ(errorOf("pause now"), "s.txt:1: pause: expected no arguments (pause), got 1");
    EXPECT_EQ(errorOf("camera-orbit 30"), "s.txt:1: camera-orbit: expected 2 arguments (camera-orbit YAW PITCH), got 1");
    EXPECT_EQ(errorOf("screenshot   # where?"), "s.txt:1: screenshot: expected 1 argument (screenshot PATH), got 0");
    EXPECT_EQ(errorOf("copy-file a b c"), "s.txt:1: copy-file: expected 2 arguments (copy-file SRC DST), got 3");
    EXPECT_EQ(errorOf("set-material m.color 1 1"),
              "s.txt:1: set-material: color: expected 3 values (set-material NAME.color R G B), got 2");
}

TEST(ViewerScript, OutputPathsNeedTheirExtension) {
    EXPECT_EQ(errorOf("screenshot shot.jpg"), "s.txt:1: screenshot: PATH must end in .png or .pfm or .exr, got \"shot.jpg\"");
    EXPECT_EQ(errorOf("screenshot-window w.pfm"), "s.txt:1: screenshot-window: PATH must end in .png, got \"w.pfm\"");
    EXPECT_EQ(errorOf("save-scene edited.txt"), "s.txt:1: save-scene: PATH must end in .json, got \"edited.txt\"");
    // The extension is compared as checkOutputPath does, ignoring case.
    EXPECT_EQ(parse("screenshot SHOT.PNG").commands[0].words, std::vector<std::string>{"SHOT.PNG"});
}

TEST(ViewerScript, FieldEditsNeedNameDotKnownField) {
    EXPECT_EQ(errorOf("set-material glass 1.5"),
              "s.txt:1: set-material: expected NAME.FIELD (FIELD: type, color, emission, ior, roughness, metallic, transmission, alpha, normal-scale, sigma-a, sigma-s, g, interior, base-color-texture, roughness-texture, metallic-texture, normal-texture, emission-texture), got \"glass\"");
    EXPECT_EQ(errorOf("set-material glass. 1.5"),
              "s.txt:1: set-material: expected NAME.FIELD (FIELD: type, color, emission, ior, roughness, metallic, transmission, alpha, normal-scale, sigma-a, sigma-s, g, interior, base-color-texture, roughness-texture, metallic-texture, normal-texture, emission-texture), got \"glass.\"");
    EXPECT_EQ(errorOf("set-material"),
              "s.txt:1: set-material: expected NAME.FIELD and its values (FIELD: type, color, emission, ior, roughness, metallic, transmission, alpha, normal-scale, sigma-a, sigma-s, g, interior, base-color-texture, roughness-texture, metallic-texture, normal-texture, emission-texture)");
    EXPECT_EQ(errorOf("set-material glass.colour 1 1 1"),
              "s.txt:1: set-material: unknown field \"colour\" (valid: type, color, emission, ior, roughness, metallic, transmission, alpha, normal-scale, sigma-a, sigma-s, g, interior, base-color-texture, roughness-texture, metallic-texture, normal-texture, emission-texture)");
    EXPECT_EQ(errorOf("set-light key.color 1 1 1"),
              "s.txt:1: set-light: unknown field \"color\" (valid: intensity, position, direction, inner-angle, "
              "outer-angle)");
}

TEST(ViewerScript, TheFirstBadLineStopsTheParse) {
    EXPECT_EQ(errorOf("depth 3\n\n# fine so far\nexposure 1.5x\ndepth 9999\n"),
              "s.txt:4: exposure: expected a number for F, got \"1.5x\"");
}

TEST(ViewerScript, LoadNamesAMissingFile) {
    std::filesystem::path missing = std::filesystem::temp_directory_path() / "ptview-no-such-script.txt";
    std::filesystem::remove(missing);
    try {
        loadViewerScript(missing);
        FAIL() << "loaded a missing file";
    } catch (const ScriptError& e) {
        EXPECT_EQ(std::string(e.what()), missing.string() + ": cannot open script: No such file or directory");
    }
}

TEST(ViewerScript, LoadReadsTheFileAndReportsItsName) {
    std::filesystem::path path = std::filesystem::temp_directory_path() / "ptview-viewer-script-test.txt";
    {
        std::ofstream file(path);
        file << "# demo\nintegrator direct\nwait-spp 16\n";
    }
    ViewerScript script = loadViewerScript(path);
    EXPECT_EQ(script.path, path);
    EXPECT_EQ(verbsOf(script), (std::vector<std::string>{"integrator", "wait-spp"}));
    EXPECT_EQ(script.commands[1].line, 3);

    {
        std::ofstream file(path);
        file << "integrator direct\ndepth -1\n";
    }
    try {
        loadViewerScript(path);
        FAIL() << "loaded a bad script";
    } catch (const ScriptError& e) {
        EXPECT_EQ(std::string(e.what()), path.string() + ":2: depth: N must be in 0..1024, got -1");
    }
    std::filesystem::remove(path);
}

// The view and zoom commands take the views' names, the zoom's range or "fit", and refuse the rest
// before any window opens.
TEST(ViewerScript, ViewAndZoomCommandsParseWithinTheirRanges) {
    ViewerScript script = parse("view difference\nzoom fit\nzoom 0.0625\nerror-range 1e-6 100\nload-compare-image none\n");
    EXPECT_EQ(errorOf("error-range 0 1"), "s.txt:1: error-range: LO must be in (0, 100], got 0");
    ASSERT_EQ(script.commands.size(), 5u);
    EXPECT_TRUE(script.commands[1].isWord(0, "fit"));
    EXPECT_FLOAT_EQ(script.commands[2].number(0), 0.0625f);
    EXPECT_EQ(errorOf("view errors"), "s.txt:1: view: unknown view \"errors\" (valid: image, error-map, estimated-error, "
                                      "difference, abs-difference, other-image, samples-per-pixel)");
    EXPECT_EQ(errorOf("zoom 128"), "s.txt:1: zoom: N must be in [0.0625, 64], got 128");
    EXPECT_EQ(errorOf("zoom"), "s.txt:1: zoom: expected 1 argument (zoom N|fit), got 0");
    EXPECT_EQ(errorOf("pan 3"), "s.txt:1: pan: expected 2 arguments (pan DX DY), got 1");
    EXPECT_EQ(errorOf("load-compare-image other.png"), "s.txt:1: load-compare-image: PATH must end in .pfm or .exr, got \"other.png\"");
}

TEST(ViewerScript, ReferenceDescribesEveryCommandAndField) {
    std::string reference = viewerScriptReference();
    EXPECT_EQ(referenceVerbs().size(), 78u);
    EXPECT_NE(reference.find("integrator NAME"), std::string::npos);
    EXPECT_NE(reference.find("NAME: one of naive, direct, mis, full"), std::string::npos) << reference;
    EXPECT_NE(reference.find("samples-per-frame N|auto"), std::string::npos);
    EXPECT_NE(reference.find("N: integer in 1..1024, or auto"), std::string::npos) << reference;
    EXPECT_NE(reference.find("    .color R G B"), std::string::npos);
    EXPECT_NE(reference.find("R G B: number in [0, 1]"), std::string::npos) << reference;
    EXPECT_NE(reference.find("    .outer-angle DEG"), std::string::npos);
    EXPECT_NE(reference.find("PATH: ends in .png or .pfm or .exr"), std::string::npos);
    EXPECT_NE(reference.find("clamp VALUE|off"), std::string::npos) << reference;
    EXPECT_NE(reference.find("camera-aperture RADIUS"), std::string::npos);
    EXPECT_NE(reference.find("RADIUS: number in [0, 1000000000]"), std::string::npos) << reference;
    EXPECT_NE(reference.find("DISTANCE: number in (0, 1000000000]"), std::string::npos) << reference;
    EXPECT_NE(reference.find("camera-focus-at X Y"), std::string::npos);
    EXPECT_NE(reference.find("denoise-strength F"), std::string::npos);
    EXPECT_NE(reference.find("F: number in [0.25, 64]"), std::string::npos) << reference;
}

// undo and redo take no arguments; a stray one is a parse error before any window opens.
TEST(ViewerScript, UndoAndRedoTakeNoArguments) {
    EXPECT_EQ(verbsOf(parse("undo\nredo\nundo\n")), (std::vector<std::string>{"undo", "redo", "undo"}));
    EXPECT_EQ(errorOf("undo 2"), "s.txt:1: undo: expected no arguments (undo), got 1");
    EXPECT_EQ(errorOf("redo all"), "s.txt:1: redo: expected no arguments (redo), got 1");
    EXPECT_NE(errorOf("undoo").find("did you mean \"undo\"?"), std::string::npos);
    EXPECT_NE(std::string(viewerScriptReference()).find("undo                              undo the last scene edit"), std::string::npos)
        << viewerScriptReference();
}

// The denoiser's commands take their ranges from SettingRanges.h, as --denoise-* and the panel do.
TEST(ViewerScript, DenoiseCommandsParseWithinTheSettingRanges) {
    ViewerScript script = parse("denoise on\ndenoise-strength 8\ndenoise-iterations 3\ncompare-sides raw-denoised\n"
                                "compare-denoise off\n");
    EXPECT_EQ(verbsOf(script), (std::vector<std::string>{"denoise", "denoise-strength", "denoise-iterations", "compare-sides",
                                                         "compare-denoise"}));
    EXPECT_TRUE(script.commands[0].isWord(0, "on"));
    EXPECT_FLOAT_EQ(script.commands[1].number(0), 8.0f);
    EXPECT_EQ(script.commands[2].integer(0), 3);
    EXPECT_TRUE(script.commands[3].isWord(0, "raw-denoised"));
    EXPECT_EQ(errorOf("denoise-strength 100"), "s.txt:1: denoise-strength: F must be in [0.25, 64], got 100");
    EXPECT_EQ(errorOf("denoise-strength 0.1"), "s.txt:1: denoise-strength: F must be in [0.25, 64], got 0.1");
    EXPECT_EQ(errorOf("denoise-iterations 9"), "s.txt:1: denoise-iterations: N must be in 1..8, got 9");
    EXPECT_EQ(errorOf("denoise-iterations 0"), "s.txt:1: denoise-iterations: N must be in 1..8, got 0");
    EXPECT_EQ(errorOf("denoise yes"), "s.txt:1: denoise: unknown value \"yes\" (valid: on, off)");
    EXPECT_EQ(errorOf("compare-sides both"), "s.txt:1: compare-sides: unknown split \"both\" (valid: renders, raw-denoised, image-view)");
}
