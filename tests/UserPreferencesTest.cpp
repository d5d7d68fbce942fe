// The viewer's per-user preferences (app/model/UserPreferences.h): kept between runs, a scale out of
// range clamped and said so, a broken file read as far as it can be, naming the file and the field.
#include <ptview/model/UserPreferences.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace ptview {
namespace {

namespace fs = std::filesystem;

class UserPreferencesFile : public ::testing::Test {
protected:
    void SetUp() override {
        directory_ = fs::temp_directory_path() / ("ptview_preferences_" + std::to_string(::getpid()));
        fs::remove_all(directory_);
    }
    void TearDown() override { fs::remove_all(directory_); }
    fs::path path() const { return directory_ / "config" / "viewer.json"; }
    void write(const std::string& text) {
        fs::create_directories(path().parent_path());
        std::ofstream(path()) << text;
    }

    fs::path directory_;
};

TEST_F(UserPreferencesFile, SavedPreferencesComeBackAndAMissingFileGivesTheDefaults) {
    std::string warning;
    UserPreferences none = loadPreferences(path(), warning);
    EXPECT_EQ(none, UserPreferences{});
    EXPECT_EQ(warning, "");

    UserPreferences chosen{1.75f, true};
    savePreferences(path(), chosen); // creates the directory
    EXPECT_EQ(loadPreferences(path(), warning), chosen);
    EXPECT_EQ(warning, "");
}

TEST_F(UserPreferencesFile, AScaleOutOfRangeIsClampedAndSaidSo) {
    write(R"({"ui_scale": 12, "high_contrast": true})");
    std::string warning;
    UserPreferences read = loadPreferences(path(), warning);
    EXPECT_EQ(read.uiScale, 3.0f);
    EXPECT_TRUE(read.highContrast);
    EXPECT_EQ(warning, path().string() + ": /ui_scale: UI scale 12 is outside [0.5, 3]: using 3");
}

TEST_F(UserPreferencesFile, ABrokenFileKeepsWhatCanBeReadAndNamesTheFileAndField) {
    write(R"({"ui_scale": "big", "high_contrast": true})");
    std::string warning;
    UserPreferences read = loadPreferences(path(), warning);
    EXPECT_EQ(read.uiScale, 1.0f);
    EXPECT_TRUE(read.highContrast);
    EXPECT_EQ(warning, path().string() + ": /ui_scale: expected a number; using 1");

    write("{not json");
    warning.clear();
    EXPECT_EQ(loadPreferences(path(), warning), UserPreferences{});
    EXPECT_EQ(warning, path().string() + ": not a JSON object; using the default preferences");
}

TEST_F(UserPreferencesFile, AFileThatCannotBeWrittenIsAnErrorNamingIt) {
    write("{}");
    fs::path blocked = path() / "viewer.json"; // under a regular file: no directory can be made there
    try {
        savePreferences(blocked, UserPreferences{});
        FAIL() << "saved under a file";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(blocked.string()), std::string::npos) << e.what();
    }
}

TEST(UiScale, ClampsToItsRangeSayingSoAndKeepsValuesInside) {
    std::string message;
    EXPECT_EQ(clampedUiScale(1.25f, &message), 1.25f);
    EXPECT_EQ(message, "");
    EXPECT_EQ(clampedUiScale(0.1f, &message), 0.5f);
    EXPECT_EQ(message, "UI scale 0.1 is outside [0.5, 3]: using 0.5");
    EXPECT_EQ(clampedUiScale(NAN, &message), 1.0f);
    EXPECT_EQ(clampedUiScale(INFINITY, nullptr), 3.0f);
    // Seven steps of Ctrl + double the scale.
    EXPECT_NEAR(std::pow(kUiScaleStep, 7.0f), 2.0f, 1e-5f);
}

TEST(UiScale, PreferencesLiveWhereTheEnvironmentSays) {
    ::setenv("PTVIEW_CONFIG", "/somewhere/prefs.json", 1);
    EXPECT_EQ(defaultPreferencesPath(), fs::path("/somewhere/prefs.json"));
    ::setenv("PTVIEW_CONFIG", "", 1);
    EXPECT_EQ(defaultPreferencesPath(), std::nullopt) << "empty: kept for this run only";
    ::unsetenv("PTVIEW_CONFIG");
    ::setenv("XDG_CONFIG_HOME", "/xdg", 1);
    EXPECT_EQ(defaultPreferencesPath(), fs::path("/xdg/ptview/viewer.json"));
    ::unsetenv("XDG_CONFIG_HOME");
    ::setenv("HOME", "/home/someone", 1);
    EXPECT_EQ(defaultPreferencesPath(), fs::path("/home/someone/.config/ptview/viewer.json"));
}

} // namespace
} // namespace ptview
