// libFuzzer target for loadEnvironmentMap: the Radiance header and resolution line, ptview's
// decoder of run-length encoded and flat scanlines (which replaced stb_image's, see
// EnvironmentMap.cpp), and the sampling distribution built from what it decodes.
//
// loadEnvironmentMap reads a file (there is no variant that takes bytes), so each input is
// written to a private directory first.
//
// An EnvironmentMapError is the documented refusal; anything else (a sanitizer report, another
// exception, a map that breaks the promises of EnvironmentMap.h, a hang) is a finding.

#include "FuzzScratch.h"
#include <ptview/scene/EnvironmentMap.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

fs::path gInput;

void require(bool holds, const char* promise) {
    if (holds) return;
    std::fprintf(stderr, "fuzz_hdr_loader: loaded map breaks a promise: %s\n", promise);
    std::abort();
}

// Nondecreasing, within [0, 1], ending at exactly 1.
bool isCdf(const float* begin, std::size_t count) {
    float previous = 0.0f;
    for (std::size_t i = 0; i < count; ++i) {
        if (!(begin[i] >= previous && begin[i] <= 1.0f)) return false;
        previous = begin[i];
    }
    return count > 0 && begin[count - 1] == 1.0f;
}

// What the renderer relies on once a map has loaded (EnvironmentMap.h).
void checkMap(const ptview::EnvironmentMap& map) {
    require(map.width >= 1 && map.height >= 1 && map.width <= ptview::kMaxEnvironmentMapSize &&
                map.height <= ptview::kMaxEnvironmentMapSize,
            "size within [1, kMaxEnvironmentMapSize]");
    const std::size_t w = static_cast<std::size_t>(map.width), h = static_cast<std::size_t>(map.height);
    require(map.rgb.size() == w * h * 3, "3 floats per texel");
    for (float radiance : map.rgb) require(std::isfinite(radiance) && radiance >= 0.0f, "finite, non-negative radiance");
    require(map.marginalCdf.size() == h && isCdf(map.marginalCdf.data(), h), "marginal CDF over the rows");
    require(map.conditionalCdf.size() == w * h, "one conditional CDF entry per texel");
    for (std::size_t row = 0; row < h; ++row)
        require(isCdf(map.conditionalCdf.data() + row * w, w), "conditional CDF per row");
    require(std::isfinite(map.meanRadiance.x) && std::isfinite(map.meanRadiance.y) &&
                std::isfinite(map.meanRadiance.z) && map.meanRadiance.x >= 0.0 && map.meanRadiance.y >= 0.0 &&
                map.meanRadiance.z >= 0.0,
            "finite, non-negative mean radiance");
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    gInput = ptview::fuzz::makeScratchDirectory("hdr") / "in.hdr";
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ptview::fuzz::writeInput(gInput, std::string_view(reinterpret_cast<const char*>(data), size));
    try {
        checkMap(ptview::loadEnvironmentMap(gInput));
    } catch (const ptview::EnvironmentMapError&) {
        // The documented refusal of a file that cannot be used.
    }
    return 0;
}
