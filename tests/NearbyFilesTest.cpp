// The files the panels offer are found near the scene, not in ptview's own tree (issue 37: the
// environment maps were listed from, and so saved as paths into, the build's source tree).
#include "TestFiles.h"
#include <ptview/model/NearbyFiles.h>

#include <gtest/gtest.h>

#include <filesystem>

namespace ptview {
namespace {

namespace fs = std::filesystem;

TEST(NearbyFiles, EnvironmentMapsAreTheOnesBesideTheScene) {
    testing::ScratchFiles files("nearby");
    const fs::path root = files.directory();
    fs::create_directories(root / "project" / "scenes" / "hdr");
    fs::create_directories(root / "project" / "hdr");
    files.write("project/scenes/beside.hdr", "");
    files.write("project/scenes/hdr/below.hdr", "");
    files.write("project/hdr/sibling.hdr", "");
    files.write("project/scenes/notes.txt", "");
    files.write("elsewhere.hdr", "");
    const fs::path scene = root / "project" / "scenes" / "room.json";
    const std::vector<fs::path> maps = environmentMapsNear(scene, PTVIEW_ASSETS_DIR "/hdr");
    std::vector<fs::path> names;
    for (const fs::path& map : maps) names.push_back(nameRelativeToScene(map, scene));
    EXPECT_EQ(names, (std::vector<fs::path>{"../hdr/sibling.hdr", "beside.hdr", "hdr/below.hdr"}));
    // Without a scene file there is no folder to look in: the maps shipped with ptview.
    const std::vector<fs::path> shipped = environmentMapsNear({}, PTVIEW_ASSETS_DIR "/hdr");
    ASSERT_FALSE(shipped.empty());
    for (const fs::path& map : shipped) EXPECT_EQ(map.extension(), ".hdr");
}

TEST(NearbyFiles, AFileOnAnotherRootKeepsItsWholePath) {
    EXPECT_EQ(nameRelativeToScene("/maps/a.hdr", "/scenes/s.json"), fs::path("../maps/a.hdr"));
    EXPECT_EQ(nameRelativeToScene("/maps/a.hdr", ""), fs::path("/maps/a.hdr"));
}

} // namespace
} // namespace ptview
