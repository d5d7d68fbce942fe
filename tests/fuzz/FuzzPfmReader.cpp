// libFuzzer target for readReferenceImage, readPfm and its check that every pixel is finite
// (`--reference` of the viewer and of `converge`): the header (magic, size, scale and the byte
// that ends it), the limits on the size, the pixel rows, stored bottom to top, and NaN or
// infinite pixels, which would make every error figure NaN.
//
// readPfm reads a file (there is no variant that takes bytes), so each input is written to a
// private directory first.
//
// A std::runtime_error whose message names the file is the documented refusal; anything else (a
// sanitizer report, another exception, a hang, an allocation beyond -rss_limit_mb, an image whose
// size disagrees with its pixel count) is a finding. A header may claim 65536 x 65536 pixels
// (48 GiB) in a file of a few bytes: such a file must be refused, not believed.

#include <ptview/metrics/ErrorMetrics.h>
#include "FuzzScratch.h"
#include <ptview/io/ImageIO.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace {

namespace fs = std::filesystem;

fs::path gInput;

void require(bool holds, const char* promise) {
    if (holds) return;
    std::fprintf(stderr, "fuzz_pfm_reader: %s\n", promise);
    std::abort();
}

// What the error metrics rely on once a reference has loaded (Image.h): a size within the
// reader's limit and three floats for each of its pixels.
void checkImage(const ptview::ImageRgbF& image) {
    require(image.width >= 1 && image.height >= 1 && image.width <= 65536 && image.height <= 65536,
            "loaded image breaks a promise: size within [1, 65536]");
    require(image.rgb.size() == static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3,
            "loaded image breaks a promise: 3 floats per pixel");
    for (float value : image.rgb) require(std::isfinite(value), "loaded reference breaks a promise: every pixel finite");
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    gInput = ptview::fuzz::makeScratchDirectory("pfm") / "in.pfm";
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ptview::fuzz::writeInput(gInput, std::string_view(reinterpret_cast<const char*>(data), size));
    try {
        checkImage(ptview::readReferenceImage(gInput));
    } catch (const std::runtime_error& error) {
        // The documented refusal of a file that cannot be used, which says which file.
        require(std::string(error.what()).rfind(gInput.string() + ": ", 0) == 0, "a refusal that does not name the file");
    }
    return 0;
}
