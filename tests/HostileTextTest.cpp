// Text from a file someone sent, printed by the real binary (issue 33): a PNG whose metadata holds
// terminal control sequences (a window title, colours, "\r" that overwrites the line, a raw C1
// CSI byte) is described by `ptview info` with every one of them shown as an escape, and with the
// scene JSON still one line per line; an error that quotes such a value escapes it too.
#include <ptview/io/ImageIO.h>
#include <ptview/io/PngText.h>
#include "RunCommand.h"
#include "TestFiles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

namespace ptview {
namespace {

namespace fs = std::filesystem;

const std::string kBinary = PTVIEW_BINARY;
const std::string kCornell = PTVIEW_ASSETS_DIR "/scenes/cornell.json";

// OSC 0 (sets the window title, ended by BEL), SGR red, a carriage return, and CSI as the raw
// byte 0x9b that terminals in 8-bit mode take as ESC [.
const std::string kHostile = std::string("\x1b]0;owned\x07") + "\x1b[31m" + "\r" + "\x9b";
// How it must be shown, written out by hand rather than computed by the function under test.
const std::string kHostileShown = "\\e]0;owned\\x07\\e[31m\\r\\x9b";

// The first byte (its offset and value) a terminal would act on, or that is not UTF-8: C0 other
// than '\n', DEL, a C1 control (U+0080..U+009F, two bytes in UTF-8), a stray or malformed byte.
// Decoded here independently of printableText, so a lenient printableText cannot pass it.
std::string firstUnsafeByte(const std::string& text) {
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char lead = static_cast<unsigned char>(text[i]);
        std::size_t length = lead < 0x80 ? 1 : (lead & 0xE0) == 0xC0 ? 2 : (lead & 0xF0) == 0xE0 ? 3 : (lead & 0xF8) == 0xF0 ? 4 : 0;
        unsigned int codePoint = length == 1 ? lead : length == 2 ? lead & 0x1Fu : length == 3 ? lead & 0x0Fu : lead & 0x07u;
        bool valid = length != 0 && i + length <= text.size();
        for (std::size_t k = 1; valid && k < length; ++k) {
            const unsigned char next = static_cast<unsigned char>(text[i + k]);
            valid = (next & 0xC0) == 0x80;
            codePoint = codePoint << 6 | (next & 0x3Fu);
        }
        const bool control = (codePoint < 0x20 && codePoint != '\n') || (codePoint >= 0x7F && codePoint <= 0x9F);
        if (!valid || control) return "offset " + std::to_string(i) + ": byte " + std::to_string(lead);
        i += length;
    }
    return "";
}

class HostileText : public ::testing::Test {
protected:
    // A PNG ptview rendered (16x16, 1 spp), so that its metadata is what ptview writes.
    fs::path renderedImage() {
        const fs::path image = dir_ / "shot.png";
        const testing::CommandResult render = testing::runCommand(
            kBinary + " render " + testing::shellQuoted(kCornell) + " --out " + testing::shellQuoted(image.string()) +
            " --spp 1 --size 16x16 --backend fragment");
        EXPECT_EQ(render.exitCode, 0) << render.output;
        return image;
    }

    // `image`'s metadata, edited, in a new PNG named `name` (a sender can write any metadata).
    fs::path withMetadata(const fs::path& image, const std::string& name, ImageMetadata metadata) {
        ImageRgba8 pixels;
        pixels.width = pixels.height = 2;
        pixels.rgba.assign(2 * 2 * 4, 200);
        const fs::path out = image.parent_path() / name;
        writePng(out, pixels, metadata);
        return out;
    }

    testing::ScratchFiles scratch_{"hostile_text"};
    const fs::path dir_ = scratch_.directory();
};

TEST_F(HostileText, InfoShowsControlSequencesInMetadataAsEscapes) {
    const fs::path image = renderedImage();
    ImageMetadata metadata = readPngTextFile(image);
    ASSERT_TRUE(metadata.find("ptview.scene"));
    std::string scene = *metadata.find("ptview.scene");
    const std::size_t white = scene.find("\"white\": {");
    ASSERT_NE(white, std::string::npos) << scene;
    // The material's line as the scene holds it (its indentation), with the hostile name.
    const std::size_t lineStart = scene.rfind('\n', white) + 1;
    const std::string indentation = scene.substr(lineStart, white - lineStart);
    scene.insert(white + 6, kHostile); // after "white
    metadata.set("ptview.version", "1.0" + kHostile);
    metadata.set("ptview.device", kHostile + "GPU");
    metadata.set("ptview.scene_file", (image.parent_path() / ("scene" + kHostile + ".json")).string());
    metadata.set("ptview.scene", scene);
    metadata.set("Comment" + kHostile, "made by" + kHostile);
    const fs::path sent = withMetadata(image, "sent.png", metadata);

    const testing::CommandResult info = testing::runCommand(kBinary + " info " + testing::shellQuoted(sent.string()));
    EXPECT_EQ(info.exitCode, 0) << info.output;
    EXPECT_EQ(firstUnsafeByte(info.output), "") << info.output;
    EXPECT_NE(info.output.find("ptview:     1.0" + kHostileShown + "\n"), std::string::npos) << info.output;
    EXPECT_NE(info.output.find("device:     " + kHostileShown + "GPU\n"), std::string::npos) << info.output;
    EXPECT_NE(info.output.find("scene file: " + (image.parent_path() / "scene").string() + kHostileShown + ".json\n"),
              std::string::npos) << info.output;
    // The scene keeps its lines: the material's is one line, indented under "scene:".
    EXPECT_NE(info.output.find("\n  " + indentation + "\"white" + kHostileShown + "\": {"), std::string::npos)
        << info.output;
    EXPECT_NE(info.output.find("\nComment" + kHostileShown + ": made by" + kHostileShown + "\n"), std::string::npos)
        << info.output;
}

// An error that quotes a value from the file (here the format, which must be a number) shows it
// escaped, on one line.
TEST_F(HostileText, InfoErrorQuotingTheFileEscapesIt) {
    const fs::path image = renderedImage();
    ImageMetadata metadata = readPngTextFile(image);
    metadata.set("ptview.format", "1" + kHostile);
    const fs::path sent = withMetadata(image, "sent.png", metadata);

    const testing::CommandResult info = testing::runCommand(kBinary + " info " + testing::shellQuoted(sent.string()));
    EXPECT_EQ(info.exitCode, 2) << info.output;
    EXPECT_EQ(firstUnsafeByte(info.output), "") << info.output;
    EXPECT_NE(info.output.find("\"1" + kHostileShown + "\" is not a number"), std::string::npos) << info.output;
    EXPECT_EQ(std::count(info.output.begin(), info.output.end(), '\n'), 1) << info.output;
}

} // namespace
} // namespace ptview
