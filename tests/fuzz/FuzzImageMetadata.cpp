// libFuzzer target for the readers of the metadata a PNG or EXR carries (`ptview info`, `render
// --from`, the viewer opening an image, EXR references): decodeExr (the OpenEXR library behind our
// size limit and channel handling) and readPngText (the chunk walk, lengths, CRCs and iTXt fields),
// then parseProvenance on whatever metadata they return. Each input goes to all of them.
//
// A std::runtime_error whose message names the source is the documented refusal; anything else (a
// sanitizer report in our code, another exception, a hang, an allocation beyond -rss_limit_mb, an
// image whose channels disagree with its size) is a finding. The OpenEXR library itself is
// Debian's build, not instrumented: a bad read inside it goes unseen here.

#include <ptview/io/ExrIO.h>
#include <ptview/io/PngText.h>
#include <ptview/provenance/Provenance.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace {

const std::string kName = "input";

void require(bool holds, const char* promise) {
    if (holds) return;
    std::fprintf(stderr, "fuzz_image_metadata: %s\n", promise);
    std::abort();
}

void checkRefusal(const std::runtime_error& error) {
    require(std::string(error.what()).rfind(kName + ": ", 0) == 0, "a refusal that does not name the file");
}

void parse(const ptview::ImageMetadata& metadata) {
    try {
        ptview::parseProvenance(metadata, kName);
    } catch (const ptview::ProvenanceError& error) {
        checkRefusal(error);
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    try {
        const ptview::ExrImage image = ptview::decodeExr(bytes, kName);
        require(image.width >= 1 && image.height >= 1, "decoded EXR breaks a promise: a size of at least 1x1");
        for (const ptview::ExrChannel& channel : image.channels)
            require(channel.values.size() == static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height),
                    "decoded EXR breaks a promise: width x height values per channel");
        parse(image.metadata);
    } catch (const std::runtime_error& error) {
        checkRefusal(error);
    }
    try {
        parse(ptview::readPngText(bytes, kName));
    } catch (const std::runtime_error& error) {
        checkRefusal(error);
    }
    return 0;
}
