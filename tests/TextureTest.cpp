// Textures: decoding (TextureLoader), and on the GPU the exact texel values a render returns.
#include "ImageIO.h"
#include "TestFiles.h"
#include "TextureLoader.h"

#include <gtest/gtest.h>

namespace ptview {
namespace {

using testing::ScratchFiles;

// A 2x2 image whose four texels differ in every channel, so any flip or transpose shows.
ImageRgba8 asymmetric2x2() {
    ImageRgba8 image;
    image.width = 2;
    image.height = 2;
    image.rgba = {10, 20, 30, 255, 200, 40, 60, 128, // top row: left, right
                  90, 250, 5, 0, 0, 0, 255, 64};     // bottom row
    return image;
}

TEST(TextureLoader, DecodesPngRowsTopFirst) {
    ScratchFiles files("texture");
    const auto path = files.write("a.png", "");
    writePng(path, asymmetric2x2());
    SceneTexture texture = loadTexture(path, TextureColorSpace::Linear, TextureWrap::ClampToEdge);
    ASSERT_TRUE(texture.image);
    EXPECT_EQ(texture.image->width, 2);
    EXPECT_EQ(texture.image->height, 2);
    EXPECT_EQ(texture.image->rgba, asymmetric2x2().rgba);
    EXPECT_EQ(texture.source, path.string());
    EXPECT_EQ(texture.colorSpace, TextureColorSpace::Linear);
    EXPECT_EQ(texture.wrapU, TextureWrap::ClampToEdge);
    EXPECT_EQ(texture.wrapV, TextureWrap::Repeat);
}

TEST(TextureLoader, CacheSharesOneImagePerFile) {
    ScratchFiles files("texture");
    const auto path = files.write("a.png", "");
    writePng(path, asymmetric2x2());
    TextureImageCache cache;
    auto first = cache.load(path);
    auto second = cache.load(path.parent_path() / "." / "a.png");
    EXPECT_EQ(first.get(), second.get());
}

TEST(TextureLoader, BadFilesNameTheFile) {
    ScratchFiles files("texture");
    auto expectError = [](const std::filesystem::path& path, const std::string& words) {
        try {
            loadTexture(path, TextureColorSpace::Srgb);
            ADD_FAILURE() << "no error for " << path;
        } catch (const TextureError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(path.string()), std::string::npos) << message;
            EXPECT_NE(message.find(words), std::string::npos) << message;
        }
    };
    expectError(files.write("text.png", "not an image at all"), "cannot decode");
    expectError(files.write("empty.png", ""), "empty");
    expectError(files.write("missing.png", "x").parent_path() / "nothere.png", "cannot open");
    // A PNG cut in the middle of its pixel data.
    const auto whole = files.write("whole.png", "");
    ImageRgba8 big;
    big.width = big.height = 64;
    for (int i = 0; i < 64 * 64 * 4; ++i) big.rgba.push_back(static_cast<std::uint8_t>(i * 7919 % 251));
    writePng(whole, big);
    const std::string bytes = testing::readFileBytes(whole);
    expectError(files.write("cut.png", bytes.substr(0, bytes.size() / 2)), "cannot decode");
}

} // namespace
} // namespace ptview
