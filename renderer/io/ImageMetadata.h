#pragma once
// Text that travels inside an image file: key/value pairs, in order, as PNG iTXt chunks and EXR
// string attributes hold them. The keys and what they mean belong to the writer (Provenance.h).

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ptview {

struct ImageMetadata {
    std::vector<std::pair<std::string, std::string>> entries;

    bool empty() const { return entries.empty(); }
    void set(const std::string& key, std::string value) {
        for (auto& entry : entries)
            if (entry.first == key) {
                entry.second = std::move(value);
                return;
            }
        entries.emplace_back(key, std::move(value));
    }
    std::optional<std::string> find(const std::string& key) const {
        for (const auto& entry : entries)
            if (entry.first == key) return entry.second;
        return std::nullopt;
    }
};

} // namespace ptview
