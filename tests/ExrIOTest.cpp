// OpenEXR files: what writeExr writes reads back through the library bit for bit (float) or to
// half precision, an independent header reader (ExrHeaderParser.h) sees the channels, compression
// and data window, the string attributes survive, and bad files are errors naming them.
#include <ptview/metrics/ErrorMetrics.h>
#include "ExrHeaderParser.h"
#include <ptview/io/ExrIO.h>
#include <ptview/io/ImageIO.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

namespace ptview {
namespace {

namespace fs = std::filesystem;

std::string readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

fs::path scratch(const std::string& name) {
    return fs::temp_directory_path() / ("ptview_exr_" + std::to_string(::getpid()) + "_" + name);
}

// Values over many magnitudes, negative ones and zero, so that every float bit matters.
ImageRgbF randomImage(int width, int height, unsigned seed) {
    ImageRgbF image(width, height);
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> exponent(-12.0f, 12.0f), sign(-1.0f, 1.0f);
    for (float& v : image.rgb) v = std::exp2(exponent(random)) * (sign(random) < -0.8f ? -1.0f : 1.0f);
    image.rgb[0] = 0.0f;
    return image;
}

ExrImage exrOf(const ImageRgbF& image) {
    ExrImage exr;
    exr.width = image.width;
    exr.height = image.height;
    exr.addRgb(image);
    exr.addComponent("Z", image, 1);
    exr.metadata.set("ptview.test", "line one\nline two, \xc3\xa9"); // UTF-8 and a newline
    return exr;
}

TEST(ExrIO, FloatChannelsReadBackBitForBitWithTheirAttributes) {
    const ImageRgbF image = randomImage(7, 5, 1);
    const fs::path path = scratch("float.exr");
    writeExr(path, exrOf(image), ExrPixelType::Float);
    const ExrImage back = readExr(path);
    fs::remove(path);
    ASSERT_EQ(back.width, 7);
    ASSERT_EQ(back.height, 5);
    const ImageRgbF rgb = exrRgb(back, path.string());
    EXPECT_EQ(std::memcmp(rgb.rgb.data(), image.rgb.data(), image.rgb.size() * sizeof(float)), 0);
    const ExrChannel* z = back.find("Z");
    ASSERT_NE(z, nullptr);
    for (int i = 0; i < 35; ++i) EXPECT_EQ(z->values[i], image.rgb[i * 3 + 1]);
    EXPECT_EQ(back.metadata.find("ptview.test").value_or(""), "line one\nline two, \xc3\xa9");
}

// Half has an 11-bit significand: a normal value rounds to within 2^-11 of itself, relative.
TEST(ExrIO, HalfChannelsHoldTheValuesToHalfPrecision) {
    ImageRgbF image = randomImage(6, 4, 2);
    for (float& v : image.rgb) v = std::clamp(v, -60000.0f, 60000.0f);
    const fs::path path = scratch("half.exr");
    writeExr(path, exrOf(image), ExrPixelType::Half);
    const ImageRgbF back = exrRgb(readExr(path), path.string());
    const testing::ParsedExrHeader header = testing::parseExrHeader(readBytes(path));
    fs::remove(path);
    ASSERT_TRUE(header.ok) << header.error;
    for (const testing::ParsedExrChannel& channel : header.channels) EXPECT_EQ(channel.pixelType, 1) << channel.name;
    int exact = 0;
    for (std::size_t i = 0; i < image.rgb.size(); ++i) {
        const float v = image.rgb[i];
        if (std::fabs(v) < 6.1e-5f) { // subnormal in half: an absolute step of 2^-24
            EXPECT_NEAR(back.rgb[i], v, 6.0e-8f) << i;
            continue;
        }
        EXPECT_LE(std::fabs(back.rgb[i] - v), std::fabs(v) * 0x1p-11f) << i << ": " << v;
        exact += back.rgb[i] == v;
    }
    EXPECT_LT(exact, static_cast<int>(image.rgb.size())); // it really was rounded to half
}

TEST(ExrIO, AnIndependentHeaderReaderSeesChannelsCompressionAndDataWindow) {
    const fs::path path = scratch("header.exr");
    writeExr(path, exrOf(randomImage(9, 3, 3)), ExrPixelType::Float);
    const testing::ParsedExrHeader header = testing::parseExrHeader(readBytes(path));
    fs::remove(path);
    ASSERT_TRUE(header.ok) << header.error;
    EXPECT_EQ(header.version, 2);
    EXPECT_EQ(header.flags & 0x200u, 0u); // scan lines, not tiles
    std::vector<std::string> names;
    for (const testing::ParsedExrChannel& channel : header.channels) {
        names.push_back(channel.name);
        EXPECT_EQ(channel.pixelType, 2) << channel.name;
        EXPECT_EQ(channel.xSampling, 1);
        EXPECT_EQ(channel.ySampling, 1);
    }
    EXPECT_EQ(names, (std::vector<std::string>{"B", "G", "R", "Z"})); // the format sorts them
    EXPECT_EQ(header.compression, 3); // ZIP
    EXPECT_EQ(header.dataWindow[0], 0);
    EXPECT_EQ(header.dataWindow[1], 0);
    EXPECT_EQ(header.dataWindow[2], 8);
    EXPECT_EQ(header.dataWindow[3], 2);
    EXPECT_EQ(header.types.at("ptview.test"), "string");
    EXPECT_EQ(header.strings.at("ptview.test"), "line one\nline two, \xc3\xa9");
}

TEST(ExrIO, TruncatedOrForeignFilesAreErrorsNamingThem) {
    const fs::path path = scratch("truncated.exr");
    writeExr(path, exrOf(randomImage(16, 16, 4)), ExrPixelType::Float);
    const std::string bytes = readBytes(path);
    for (std::size_t keep : {bytes.size() / 2, std::size_t(40), std::size_t(3), std::size_t(0)}) {
        std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes.substr(0, keep);
        try {
            readExr(path);
            ADD_FAILURE() << "a file cut to " << keep << " bytes was read";
        } catch (const std::runtime_error& e) {
            EXPECT_EQ(std::string(e.what()).rfind(path.string() + ": ", 0), 0u) << e.what();
        }
    }
    std::ofstream(path, std::ios::binary | std::ios::trunc) << "PF\n1 1\n-1.0\n0000";
    EXPECT_THROW(readExr(path), std::runtime_error);
    fs::remove(path);
}

// OpenEXR sizes a string attribute by the length its header declares before reading it: a
// 426-byte file declaring a 1.8 GB string took 1.8 GB and 7 s (found by the metadata fuzz target).
// An attribute declaring more bytes than the file has left is refused, naming it, before the
// library allocates anything for it.
TEST(ExrIO, AnAttributeDeclaringMoreBytesThanTheFileHoldsIsRefusedUnread) {
    std::string bytes = encodeExr(exrOf(randomImage(4, 4, 6)), ExrPixelType::Float);
    const std::string key = std::string("ptview.test") + '\0' + "string" + '\0';
    const std::size_t at = bytes.find(key);
    ASSERT_NE(at, std::string::npos);
    const std::uint32_t claimed = 0x7ffffff0u;
    for (int i = 0; i < 4; ++i) bytes[at + key.size() + static_cast<std::size_t>(i)] = static_cast<char>(claimed >> (8 * i) & 0xff);
    try {
        decodeExr(bytes, "sent.exr");
        ADD_FAILURE() << "an attribute of 2 GiB in a file of " << bytes.size() << " bytes was read";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("sent.exr: not a readable EXR file: its header attribute \"ptview.test\" (string) "
                                              "declares 2147483632 bytes, more than the",
                                              0),
                  0u)
            << e.what();
    }
}

// converge --reference and the viewer's reference read through readReferenceImage.
TEST(ExrIO, ReferenceImagesMayBeExrAsWellAsPfm) {
    const ImageRgbF image = randomImage(5, 4, 5);
    const fs::path exr = scratch("reference.exr"), pfm = scratch("reference.pfm");
    writeExr(exr, exrOf(image), ExrPixelType::Float);
    writePfm(pfm, image);
    const ImageRgbF fromExr = readReferenceImage(exr), fromPfm = readReferenceImage(pfm);
    fs::remove(exr);
    fs::remove(pfm);
    EXPECT_EQ(fromExr.rgb, image.rgb);
    EXPECT_EQ(fromPfm.rgb, image.rgb);
}

} // namespace
} // namespace ptview
