// The real viewer in a real window under Xvfb: it opens, renders frames, and the screenshot shows
// the converging image with the ImGui panel over it.
#include "RunCommand.h"

#include <stb_image.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <unistd.h>

namespace ptview {
namespace {

namespace fs = std::filesystem;

TEST(WindowSmoke, ViewerRendersCornellBoxWithPanel) {
    ASSERT_EQ(testing::runCommand("command -v xvfb-run").exitCode, 0)
        << "xvfb-run is missing: scripts/test installs the xvfb package";
    fs::path screenshot = fs::temp_directory_path() / ("ptview_window_" + std::to_string(::getpid()) + ".png");
    fs::path script = fs::temp_directory_path() / ("ptview_window_" + std::to_string(::getpid()) + ".txt");
    // Waiting for samples, not frames: how many samples a frame holds depends on the machine's load.
    // Naive, as the default was when this was written: the test is about the window, and naive
    // gives the cheapest 4 samples of the 768x768 image within wait-spp's 120 s.
    // At half the window's resolution (shown scaled to it), so that a loaded machine still has
    // the samples well within that time.
    std::ofstream(script) << "integrator naive\nresolution-scale 0.5\ntarget-spp 4\nwait-spp 4\nscreenshot-window " << screenshot.string()
                          << "\nquit\n";
    testing::CommandResult result = testing::runCommand(
        "xvfb-run -a -s '-screen 0 1600x1000x24' " + std::string(PTVIEW_BINARY) + " " +
        testing::shellQuoted(PTVIEW_ASSETS_DIR "/scenes/cornell.json") + " --script " + testing::shellQuoted(script.string()));
    fs::remove(script);
    ASSERT_EQ(result.exitCode, 0) << result.output;

    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(screenshot.string().c_str(), &width, &height, &channels, 3);
    ASSERT_NE(pixels, nullptr) << result.output;
    // The 256x256 scene, scaled up to a usable image, to the right of the 380-pixel sidebar.
    const int sidebar = 380;
    EXPECT_EQ(width, sidebar + 768);
    EXPECT_EQ(height, 768);

    // Not blank: many distinct colours, and the red and green walls where they belong.
    std::set<int> colours;
    long redWall = 0, greenWall = 0, panelHeaders = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const unsigned char* p = pixels + 3 * (y * width + x);
            colours.insert(p[0] << 16 | p[1] << 8 | p[2]);
            if (y > height / 4 && y < 3 * height / 4) {
                if (x >= sidebar && x < sidebar + 96 && p[0] > 2 * p[1] + 20) ++redWall;
                if (x > width - 96 && p[1] > p[0] + 20) ++greenWall;
            }
            // The sidebar's collapsing headers (ImGui's dark style: (30, 56, 87) over the window).
            if (x < sidebar && std::abs(p[0] - 30) < 6 && std::abs(p[1] - 56) < 6 && std::abs(p[2] - 87) < 6) ++panelHeaders;
        }
    }
    stbi_image_free(pixels);
    fs::remove(screenshot);
    EXPECT_GT(colours.size(), 250u);
    EXPECT_GT(redWall, 300);
    EXPECT_GT(greenWall, 300);
    EXPECT_GT(panelHeaders, 3000) << "the sidebar's panels should be in the screenshot";
}

TEST(WindowSmoke, WarpVisualizerDrawsPointsInTheViewer) {
    fs::path screenshot = fs::temp_directory_path() / ("ptview_warp_window_" + std::to_string(::getpid()) + ".png");
    testing::CommandResult result = testing::runCommand(
        "xvfb-run -a -s '-screen 0 1024x800x24' " + std::string(PTVIEW_BINARY) +
        " --warp uniform-sphere --sampler sobol --frames 2 --screenshot " + testing::shellQuoted(screenshot.string()));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("(0 spp)"), std::string::npos) << "the path tracer pauses in the visualizer";
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(screenshot.string().c_str(), &width, &height, &channels, 3);
    ASSERT_NE(pixels, nullptr);
    // Points are coloured by (u.x, u.y): strongly red-not-green and green-not-red points both appear
    // in the lower right quarter, away from the panels.
    long reddish = 0, greenish = 0;
    for (int y = height / 2; y < height; ++y)
        for (int x = width / 2; x < width; ++x) {
            const unsigned char* p = pixels + 3 * (y * width + x);
            reddish += p[0] > p[1] + 60;
            greenish += p[1] > p[0] + 60;
        }
    stbi_image_free(pixels);
    fs::remove(screenshot);
    EXPECT_GT(reddish, 200);
    EXPECT_GT(greenish, 200);
}

TEST(WindowSmoke, ViewerSurvivesResizingAndQuitsWithEscape) {
    ASSERT_EQ(testing::runCommand("command -v xvfb-run && command -v xdotool").exitCode, 0)
        << "xvfb-run or xdotool is missing: scripts/test installs them";
    testing::CommandResult result = testing::runCommand(
        "xvfb-run -a -s '-screen 0 1280x1024x24' " + testing::shellQuoted(PTVIEW_TEST_SCRIPT_DIR "/window_resize.sh") +
        " " + std::string(PTVIEW_BINARY) + " " + testing::shellQuoted(PTVIEW_ASSETS_DIR "/scenes/cornell.json"));
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("viewer exit code 0"), std::string::npos) << result.output;
}

} // namespace
} // namespace ptview
