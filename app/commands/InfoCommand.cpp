#include <ptview/commands/InfoCommand.h>

#include <ptview/commands/CommandErrors.h>
#include <ptview/io/ExrIO.h>
#include <ptview/io/ImageIO.h>
#include <ptview/io/PrintableText.h>
#include <ptview/provenance/Provenance.h>

#include <cstdio>
#include <string>

namespace ptview {
namespace {

// Everything printed below came from a file someone may have sent: each line goes through
// printableText, so that an escape sequence in a value cannot set the terminal's title or
// colours, nor a "\r" overwrite what was printed before it.
void printLine(const std::string& text) {
    std::printf("%s\n", printableText(text).c_str());
}

// Each line of a multi-line value indented under its label. Split at '\n' before escaping, so the
// scene JSON keeps its lines while a "\r" or ESC inside one is shown as an escape.
void printIndented(const std::string& text) {
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        printLine("  " + text.substr(start, end - start));
        start = end + 1;
    }
}

} // namespace

int runInfoCommand(const InfoOptions& options) {
    try {
        ImageMetadata metadata;
        std::string heading = options.path + ":";
        if (hasExrExtension(options.path)) {
            const ExrImage image = readExr(options.path);
            heading += " OpenEXR, " + std::to_string(image.width) + "x" + std::to_string(image.height) + ", channels:";
            for (const ExrChannel& channel : image.channels) heading += " " + channel.name;
            metadata = image.metadata;
        } else {
            metadata = readImageMetadata(options.path);
        }
        const Provenance provenance = parseProvenance(metadata, options.path); // before any output: an error is one line
        printLine(heading);
        std::printf("format:     %d\n", provenance.format);
        printLine("ptview:     " + provenance.version);
        printLine("device:     " + provenance.device);
        printLine("scene file: " + provenance.sceneFile.string());
        std::printf("settings:\n");
        printIndented(recipeToJson(provenance.recipe));
        std::printf("scene:\n");
        printIndented(provenance.sceneJson);
        for (const auto& [key, value] : metadata.entries)
            if (key.rfind("ptview.", 0) != 0) {
                // A value of several lines keeps them, indented, as the scene does.
                if (value.find('\n') == std::string::npos) {
                    printLine(key + ": " + value);
                } else {
                    printLine(key + ":");
                    printIndented(value);
                }
            }
        printLine("render it again: ptview render --from " + options.path + " --out FILE");
        return 0;
    } catch (const std::exception& e) { // ProvenanceError and the readers' errors name the file
        printMessage(e.what());
        return kExitBadInput;
    }
}

} // namespace ptview
