#pragma once
// The denoiser's filters (docs/denoising.md), and their names on the command line, in
// provenance, in `converge` configurations and in the viewer.

#include <ptview/settings/EnumTable.h>

#include <cstdint>

namespace ptview {

enum class DenoiseAlgorithm : std::uint32_t { Atrous = 0, Regression = 1 };

// The first entry is what a file without the setting meant: it was written before there was a
// choice, by the à-trous filter.
inline const EnumTable<DenoiseAlgorithm>& denoiseAlgorithmNames() {
    static const EnumTable<DenoiseAlgorithm> table = {
        {DenoiseAlgorithm::Atrous, "atrous", "a-trous",
         "edge-avoiding a-trous wavelet filter guided by the variance (SVGF's spatial part): fast, for the viewer"},
        {DenoiseAlgorithm::Regression, "regression", nullptr,
         "first-order regression on the features with non-local-means weights (after NFOR, Bitterli et al. 2016): "
         "slower, less bias at creases and gradients, for final renders"},
    };
    return table;
}

inline const char* denoiseAlgorithmName(DenoiseAlgorithm algorithm) { return denoiseAlgorithmNames().name(algorithm); }

} // namespace ptview
