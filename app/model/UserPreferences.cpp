#include <ptview/model/UserPreferences.h>

#include <ptview/io/ImageIO.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace ptview {

std::optional<std::filesystem::path> defaultPreferencesPath() {
    if (const char* path = std::getenv("PTVIEW_CONFIG"))
        return *path ? std::optional<std::filesystem::path>(path) : std::nullopt;
    if (const char* config = std::getenv("XDG_CONFIG_HOME"); config && *config)
        return std::filesystem::path(config) / "ptview" / "viewer.json";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".config" / "ptview" / "viewer.json";
    return std::nullopt;
}

float clampedUiScale(float requested, std::string* message) {
    if (kUiScale.contains(requested)) return requested;
    float clamped = std::isnan(requested) ? 1.0f
                                          : static_cast<float>(std::fmin(std::fmax(requested, kUiScale.lo), kUiScale.hi));
    if (message) {
        char text[128];
        std::snprintf(text, sizeof text, "UI scale %g is outside %s: using %g", static_cast<double>(requested),
                      kUiScale.text().substr(3).c_str(), static_cast<double>(clamped));
        *message = text;
    }
    return clamped;
}

UserPreferences loadPreferences(const std::filesystem::path& path, std::string& warning) {
    UserPreferences preferences;
    std::ifstream in(path, std::ios::binary);
    if (!in) return preferences; // none saved yet
    std::ostringstream bytes;
    bytes << in.rdbuf();
    nlohmann::json json = nlohmann::json::parse(bytes.str(), nullptr, false);
    if (json.is_discarded() || !json.is_object()) {
        warning = path.string() + ": not a JSON object; using the default preferences";
        return preferences;
    }
    std::string problems;
    auto note = [&](const std::string& text) { problems += (problems.empty() ? "" : "; ") + text; };
    if (auto scale = json.find("ui_scale"); scale != json.end()) {
        if (scale->is_number()) {
            std::string clampMessage;
            preferences.uiScale = clampedUiScale(scale->get<float>(), &clampMessage);
            if (!clampMessage.empty()) note("/ui_scale: " + clampMessage);
        } else {
            note("/ui_scale: expected a number; using 1");
        }
    }
    if (auto contrast = json.find("high_contrast"); contrast != json.end()) {
        if (contrast->is_boolean()) preferences.highContrast = contrast->get<bool>();
        else note("/high_contrast: expected true or false; using false");
    }
    if (!problems.empty()) warning = path.string() + ": " + problems;
    return preferences;
}

void savePreferences(const std::filesystem::path& path, const UserPreferences& preferences) {
    nlohmann::json json = {{"ui_scale", preferences.uiScale}, {"high_contrast", preferences.highContrast}};
    try {
        if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
        writeFileAtomically(path, json.dump(1) + "\n");
    } catch (const std::exception& e) {
        throw std::runtime_error("cannot keep the preferences in " + path.string() + ": " + e.what());
    }
}

} // namespace ptview
