#pragma once
// How `--backend auto` picks the fragment or the compute backend, reproducibly: alternating timed
// rounds of the same work, a decision rule with a margin, and a cache of the decision per device
// and program, so the same scene on the same machine runs the same backend every time (a
// one-pass measurement picked compute in one run and fragment in the next). No OpenGL here: the
// path tracer measures (PathTracer::chooseBackend), this decides and remembers.

#include <ptview/settings/Backend.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ptview {

// One round: the seconds each backend took for the same passes at the same size.
struct BackendTiming {
    double fragmentSeconds = 0.0;
    double computeSeconds = 0.0;
};

struct BackendChoice {
    Backend backend = Backend::Fragment;
    // fragment time / compute time, the median over the rounds; 0: the context has no compute
    // shaders (below OpenGL 4.3), so nothing was measured.
    double computeSpeedup = 1.0;
    bool fromCache = false;
    // Chosen for adaptive sampling, unmeasured: only the compute backend packs its passes with
    // the pixels still sampled (PathTracer::chooseBackendForAdaptiveSampling).
    bool forAdaptiveSampling = false;
    // "compute, 1.84x the fragment backend's speed (measured)", for reports and the Render panel.
    std::string describe() const;
};

// Compute only when it is faster by the margin in the median round; otherwise fragment, the path
// every device has (OpenGL 4.1). The median of per-round ratios ignores a round that a busy
// machine slowed; the margin keeps a near tie from flipping between runs.
inline constexpr double kComputeMargin = 1.1;
BackendChoice decideBackend(const std::vector<BackendTiming>& rounds);

// What identifies a decision: the OpenGL device and driver, and the program (both backends'
// assembled sources, which carry its feature set, integrator, sampler and view): a hash of them.
std::string backendCacheKey(const std::string& device, const std::string& program);

// $PTVIEW_BACKEND_CACHE if set (empty: no cache), else $XDG_CACHE_HOME/ptview/backends.json,
// else ~/.cache/ptview/backends.json; nullopt where none of them is set.
std::optional<std::filesystem::path> defaultBackendCachePath();

// A JSON file of decisions by key. A cache that cannot be read or written costs a measurement
// and a warning on stderr, never the render: it is only ever a shortcut.
class BackendCache {
public:
    explicit BackendCache(std::optional<std::filesystem::path> path = defaultBackendCachePath());
    std::optional<BackendChoice> find(const std::string& key) const;
    void store(const std::string& key, const BackendChoice& choice) const; // written atomically
    const std::optional<std::filesystem::path>& path() const { return path_; }

private:
    std::optional<std::filesystem::path> path_;
};

} // namespace ptview
