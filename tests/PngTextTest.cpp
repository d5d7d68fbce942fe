// PNG text: the iTXt chunks insertPngText adds are where the PNG specification puts them, with
// correct CRCs (checked by a chunk walker and a bitwise CRC written here, not the code under test),
// the image still decodes to the same pixels, and readPngText reads the entries back.
#include <ptview/io/ImageIO.h>
#include <ptview/io/PngText.h>

#include <stb_image.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace ptview {
namespace {

namespace fs = std::filesystem;

// CRC-32 bit by bit from the polynomial (PNG specification, Annex D), no table.
std::uint32_t bitwiseCrc(const std::string& bytes) {
    std::uint32_t crc = 0xffffffffu;
    for (unsigned char byte : bytes) {
        crc ^= byte;
        for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

struct WalkedChunk {
    std::string type, data;
    bool crcOk = false;
};

std::vector<WalkedChunk> walk(const std::string& png) {
    std::vector<WalkedChunk> chunks;
    std::size_t at = 8;
    auto be32 = [&](std::size_t i) {
        return (std::uint32_t(static_cast<unsigned char>(png[i])) << 24) | (std::uint32_t(static_cast<unsigned char>(png[i + 1])) << 16) |
               (std::uint32_t(static_cast<unsigned char>(png[i + 2])) << 8) | std::uint32_t(static_cast<unsigned char>(png[i + 3]));
    };
    while (at + 12 <= png.size()) {
        const std::uint32_t length = be32(at);
        if (at + 12 + length > png.size()) break;
        WalkedChunk chunk{png.substr(at + 4, 4), png.substr(at + 8, length)};
        chunk.crcOk = bitwiseCrc(chunk.type + chunk.data) == be32(at + 8 + length);
        chunks.push_back(chunk);
        at += 12 + length;
    }
    return chunks;
}

std::string readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

ImageRgba8 smallImage() {
    ImageRgba8 image{3, 2, {}};
    for (int i = 0; i < 24; ++i) image.rgba.push_back(static_cast<std::uint8_t>(i * 10));
    return image;
}

TEST(PngText, ITxtChunksComeBeforeIendWithCorrectCrcsAndThePixelsStay) {
    ImageMetadata metadata;
    metadata.set("ptview.format", "1");
    metadata.set("ptview.scene", "{\n  \"camera\": {}\n}  caf\xc3\xa9");
    const fs::path path = fs::temp_directory_path() / ("ptview_pngtext_" + std::to_string(::getpid()) + ".png");
    writePng(path, smallImage(), metadata);
    const std::string bytes = readBytes(path);
    const std::vector<WalkedChunk> chunks = walk(bytes);
    ASSERT_GE(chunks.size(), 5u);
    EXPECT_EQ(chunks.front().type, "IHDR");
    EXPECT_EQ(chunks.back().type, "IEND");
    std::vector<WalkedChunk> texts;
    for (const WalkedChunk& chunk : chunks) {
        EXPECT_TRUE(chunk.crcOk) << chunk.type;
        if (chunk.type == "iTXt") texts.push_back(chunk);
    }
    ASSERT_EQ(texts.size(), 2u);
    EXPECT_EQ(chunks[chunks.size() - 2].type, "iTXt"); // after the image data, before IEND
    // keyword NUL, compression flag 0, method 0, language NUL, translated keyword NUL, text
    EXPECT_EQ(texts[0].data, std::string("ptview.format\0\0\0\0\0" "1", 19));
    EXPECT_EQ(texts[1].data.substr(0, 18), std::string("ptview.scene\0\0\0\0\0{", 18));

    int width = 0, height = 0, channels = 0;
    stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), static_cast<int>(bytes.size()),
                                            &width, &height, &channels, 4);
    ASSERT_NE(pixels, nullptr);
    EXPECT_EQ(std::vector<std::uint8_t>(pixels, pixels + 24), smallImage().rgba);
    stbi_image_free(pixels);

    const ImageMetadata back = readPngTextFile(path);
    fs::remove(path);
    EXPECT_EQ(back.entries, metadata.entries);
}

TEST(PngText, AWrongCrcOrATruncatedFileIsAnErrorNamingIt) {
    ImageMetadata metadata;
    metadata.set("key", "value");
    const fs::path path = fs::temp_directory_path() / ("ptview_pngcrc_" + std::to_string(::getpid()) + ".png");
    writePng(path, smallImage(), metadata);
    std::string bytes = readBytes(path);
    const std::size_t text = bytes.find("iTXt");
    ASSERT_NE(text, std::string::npos);
    std::string corrupt = bytes;
    corrupt[text + 6] ^= 1; // a byte of the keyword
    std::ofstream(path, std::ios::binary | std::ios::trunc) << corrupt;
    try {
        readPngTextFile(path);
        ADD_FAILURE() << "a wrong CRC was accepted";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path.string() + ": PNG chunk iTXt"), std::string::npos) << e.what();
    }
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() - 6);
    EXPECT_THROW(readPngTextFile(path), std::runtime_error);
    fs::remove(path);
}

TEST(PngText, CrcMatchesTheSpecificationsCheckValue) {
    EXPECT_EQ(pngCrc("123456789"), 0xcbf43926u); // the CRC-32 check value
    EXPECT_EQ(pngCrc("IEND"), 0xae426082u);      // every PNG ends with these bytes
}

} // namespace
} // namespace ptview
