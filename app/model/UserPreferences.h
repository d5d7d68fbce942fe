#pragma once
// What a user sets once for every scene and keeps between runs: the size of the interface (for a
// projector or a high-DPI screen beyond what the monitor reports) and a high-contrast theme. Kept
// as JSON in $PTVIEW_CONFIG (a file), else $XDG_CONFIG_HOME/ptview/viewer.json, else
// ~/.config/ptview/viewer.json; written atomically whenever the user changes them.

#include <ptview/settings/NumberRange.h>

#include <filesystem>
#include <optional>
#include <string>

namespace ptview {

// The interface scale on top of the monitor's content scale: 0.5 (half size) to 3.
inline const NumberRange kUiScale{"UI scale", 0.5, 3.0, false, false, "",
                                  "size of the panels' text and widgets, on top of the monitor's scale", 0.5f, 3.0f};
// Ctrl + and Ctrl - step the scale by this factor (seven steps double it).
constexpr float kUiScaleStep = 1.10408951f; // 2^(1/7)

struct UserPreferences {
    float uiScale = 1.0f;
    bool highContrast = false;

    bool operator==(const UserPreferences& other) const {
        return uiScale == other.uiScale && highContrast == other.highContrast;
    }
    bool operator!=(const UserPreferences& other) const { return !(*this == other); }
};

// Where the preferences are kept; nullopt when no place is known (no HOME): they then last one run.
std::optional<std::filesystem::path> defaultPreferencesPath();

// `requested` clamped into kUiScale; `message` says so when it had to ("UI scale 5 is outside
// [0.5, 3]: using 3"), and is left alone otherwise. NaN gives 1.
float clampedUiScale(float requested, std::string* message);

// The preferences in `path`: the defaults for a missing file; for a file that is not valid JSON or
// holds a value of the wrong type, the defaults for what cannot be read, and `warning` names the
// file and the field. An out-of-range scale is clamped, and said so in `warning`.
UserPreferences loadPreferences(const std::filesystem::path& path, std::string& warning);
// Throws std::runtime_error naming the file when it cannot be written; never leaves half a file.
void savePreferences(const std::filesystem::path& path, const UserPreferences& preferences);

} // namespace ptview
