#include <ptview/tracer/BackendChoice.h>

#include <ptview/io/ImageIO.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace ptview {

std::string BackendChoice::describe() const {
    if (computeSpeedup <= 0.0) return std::string(backendName(backend)) + " (this context has no compute shaders)";
    if (forAdaptiveSampling)
        return std::string(backendName(backend)) + " (adaptive sampling: its passes trace only the pixels still sampled there)";
    char speed[64];
    std::snprintf(speed, sizeof speed, "%.2fx", computeSpeedup);
    return std::string(backendName(backend)) + ", compute at " + speed + " the fragment backend's speed (" +
           (fromCache ? "cached measurement" : "measured") + ")";
}

BackendChoice decideBackend(const std::vector<BackendTiming>& rounds) {
    if (rounds.empty()) throw std::invalid_argument("decideBackend: no timed rounds");
    std::vector<double> speedups;
    for (const BackendTiming& round : rounds)
        speedups.push_back(round.fragmentSeconds / std::max(round.computeSeconds, 1e-12));
    std::sort(speedups.begin(), speedups.end());
    const std::size_t n = speedups.size();
    BackendChoice choice;
    choice.computeSpeedup = n % 2 ? speedups[n / 2] : 0.5 * (speedups[n / 2 - 1] + speedups[n / 2]);
    choice.backend = choice.computeSpeedup >= kComputeMargin ? Backend::Compute : Backend::Fragment;
    return choice;
}

namespace {

// FNV-1a, 64 bits: a hash that is the same in every build and on every machine, unlike std::hash.
std::uint64_t fnv1a(const std::string& text) {
    std::uint64_t hash = 14695981039346656037ull;
    for (unsigned char c : text) {
        hash ^= c;
        hash *= 1099511628211ull;
    }
    return hash;
}

nlohmann::json readCacheFile(const std::filesystem::path& path) {
    std::ifstream file(path);
    if (!file) return nlohmann::json::object(); // no cache yet
    nlohmann::json json = nlohmann::json::parse(file, nullptr, false);
    if (json.is_discarded() || !json.is_object()) {
        std::fprintf(stderr, "ptview: warning: %s: not a backend cache (JSON object); measuring again\n",
                     path.string().c_str());
        return nlohmann::json::object();
    }
    return json;
}

} // namespace

std::string backendCacheKey(const std::string& device, const std::string& program) {
    char hash[17];
    std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(fnv1a(device + "\n" + program)));
    return hash;
}

std::optional<std::filesystem::path> defaultBackendCachePath() {
    if (const char* path = std::getenv("PTVIEW_BACKEND_CACHE"))
        return *path ? std::optional<std::filesystem::path>(path) : std::nullopt;
    if (const char* cache = std::getenv("XDG_CACHE_HOME"); cache && *cache)
        return std::filesystem::path(cache) / "ptview" / "backends.json";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".cache" / "ptview" / "backends.json";
    return std::nullopt;
}

BackendCache::BackendCache(std::optional<std::filesystem::path> path) : path_(std::move(path)) {}

std::optional<BackendChoice> BackendCache::find(const std::string& key) const {
    if (!path_) return std::nullopt;
    nlohmann::json json = readCacheFile(*path_);
    auto entry = json.find(key);
    if (entry == json.end() || !entry->is_object()) return std::nullopt;
    std::optional<Backend> backend = backendNames().parse(entry->value("backend", std::string()));
    auto speedup = entry->find("compute_speedup");
    if (!backend || speedup == entry->end() || !speedup->is_number()) return std::nullopt;
    BackendChoice choice;
    choice.backend = *backend;
    choice.computeSpeedup = speedup->get<double>();
    choice.fromCache = true;
    return choice;
}

void BackendCache::store(const std::string& key, const BackendChoice& choice) const {
    if (!path_) return;
    try {
        nlohmann::json json = readCacheFile(*path_);
        json[key] = {{"backend", backendName(choice.backend)}, {"compute_speedup", choice.computeSpeedup}};
        if (path_->has_parent_path()) std::filesystem::create_directories(path_->parent_path());
        writeFileAtomically(*path_, json.dump(1) + "\n");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ptview: warning: cannot keep the backend choice in %s: %s\n", path_->string().c_str(),
                     e.what());
    }
}

} // namespace ptview
