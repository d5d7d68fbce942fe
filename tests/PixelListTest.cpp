// The compute backend's list of the pixels adaptive sampling still samples
// (renderer/tracer/PixelList.h): exactly those pixels, each once, in GL window coordinates, 4x2
// blocks at a time. AdaptiveSamplerTest's StoppedPixels checks the passes that use it.
#include <ptview/tracer/PixelList.h>

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <utility>

namespace ptview {
namespace {

glm::ivec2 unpacked(std::uint32_t entry) { return {int(entry & 0xffffu), int(entry >> 16)}; }

TEST(PixelList, HoldsEachPixelStillSampledOnceWithRowsFromTheBottom) {
    const glm::ivec2 size(10, 5); // neither side a multiple of the block's
    std::vector<std::uint8_t> stopped(size_t(size.x * size.y), 0);
    for (int row = 0; row < size.y; ++row)
        for (int x = 0; x < size.x; ++x) stopped[size_t(row * size.x + x)] = (x + 2 * row) % 3 == 0 ? 1 : 0;
    const std::vector<std::uint32_t> list = packedPixelsStillSampled(stopped, size);
    std::set<std::pair<int, int>> seen;
    for (std::uint32_t entry : list) {
        const glm::ivec2 pixel = unpacked(entry);
        ASSERT_GE(pixel.x, 0);
        ASSERT_LT(pixel.x, size.x);
        ASSERT_GE(pixel.y, 0);
        ASSERT_LT(pixel.y, size.y);
        const int row = size.y - 1 - pixel.y; // the flags' rows run from the top
        EXPECT_EQ(stopped[size_t(row * size.x + pixel.x)], 0) << pixel.x << " " << pixel.y;
        EXPECT_TRUE(seen.insert({pixel.x, pixel.y}).second) << "twice: " << pixel.x << " " << pixel.y;
    }
    size_t stillSampled = 0;
    for (std::uint8_t flag : stopped) stillSampled += flag ? 0 : 1;
    EXPECT_EQ(list.size(), stillSampled);
}

TEST(PixelList, RunsThroughFourByTwoBlocksInRows) {
    const glm::ivec2 size(8, 4);
    const std::vector<std::uint8_t> none(size_t(size.x * size.y), 0);
    const std::vector<std::uint32_t> list = packedPixelsStillSampled(none, size);
    ASSERT_EQ(list.size(), 32u);
    // Each run of eight is one block: x in [4b, 4b + 4), two rows.
    for (size_t run = 0; run < 4; ++run) {
        const glm::ivec2 corner(int(run % 2) * 4, int(run / 2) * 2);
        for (size_t lane = 0; lane < 8; ++lane)
            EXPECT_EQ(unpacked(list[run * 8 + lane]), corner + glm::ivec2(int(lane % 4), int(lane / 4))) << run << " " << lane;
    }
}

TEST(PixelList, AllStoppedIsEmptyAndAWrongSizeIsRefused) {
    const glm::ivec2 size(3, 3);
    EXPECT_TRUE(packedPixelsStillSampled(std::vector<std::uint8_t>(9, 1), size).empty());
    EXPECT_THROW(packedPixelsStillSampled(std::vector<std::uint8_t>(8, 0), size), std::invalid_argument);
    EXPECT_THROW(packedPixelsStillSampled({}, glm::ivec2(0, 0)), std::invalid_argument);
}

} // namespace
} // namespace ptview
