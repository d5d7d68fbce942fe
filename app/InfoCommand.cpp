#include "InfoCommand.h"

#include "ExrIO.h"
#include "ImageIO.h"
#include "Provenance.h"

#include <cstdio>
#include <iostream>
#include <string>

namespace ptview {
namespace {

// Each line of a multi-line value indented under its label.
void printIndented(const std::string& text) {
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        std::printf("  %s\n", text.substr(start, end - start).c_str());
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
        std::printf("%s\n", heading.c_str());
        std::printf("format:     %d\n", provenance.format);
        std::printf("ptview:     %s\n", provenance.version.c_str());
        std::printf("device:     %s\n", provenance.device.c_str());
        std::printf("scene file: %s\n", provenance.sceneFile.string().c_str());
        std::printf("settings:\n");
        printIndented(recipeToJson(provenance.recipe));
        std::printf("scene:\n");
        printIndented(provenance.sceneJson);
        for (const auto& [key, value] : metadata.entries)
            if (key.rfind("ptview.", 0) != 0) std::printf("%s: %s\n", key.c_str(), value.c_str());
        std::printf("render it again: ptview render --from %s --out FILE\n", options.path.c_str());
        return 0;
    } catch (const std::exception& e) { // ProvenanceError and the readers' errors name the file
        std::cerr << "ptview: " << e.what() << "\n";
        return kExitBadInput;
    }
}

} // namespace ptview
