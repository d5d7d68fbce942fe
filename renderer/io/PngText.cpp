#include <ptview/io/PngText.h>

#include <ptview/io/InputFile.h>

#include <array>
#include <stdexcept>

namespace ptview {
namespace {

const std::string kSignature = "\x89PNG\r\n\x1a\n";

std::uint32_t readBigEndian32(const std::string& bytes, std::size_t at) {
    return (std::uint32_t(static_cast<unsigned char>(bytes[at])) << 24) |
           (std::uint32_t(static_cast<unsigned char>(bytes[at + 1])) << 16) |
           (std::uint32_t(static_cast<unsigned char>(bytes[at + 2])) << 8) | std::uint32_t(static_cast<unsigned char>(bytes[at + 3]));
}

void appendBigEndian32(std::string& bytes, std::uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) bytes.push_back(static_cast<char>((value >> shift) & 0xff));
}

std::string chunk(const std::string& type, const std::string& data) {
    std::string bytes;
    appendBigEndian32(bytes, static_cast<std::uint32_t>(data.size()));
    const std::string typed = type + data;
    bytes += typed;
    appendBigEndian32(bytes, pngCrc(typed));
    return bytes;
}

struct Chunk {
    std::size_t start; // of its length field
    std::string type;
    std::string data;
};

// Calls visit(chunk) for each chunk up to and including IEND; checks lengths and CRCs.
template <typename Visit>
void walkChunks(const std::string& png, const std::string& name, Visit visit) {
    if (png.compare(0, kSignature.size(), kSignature) != 0) throw std::runtime_error(name + ": not a PNG file");
    std::size_t at = kSignature.size();
    while (true) {
        if (png.size() - at < 12) throw std::runtime_error(name + ": truncated PNG (no IEND chunk)");
        const std::uint32_t length = readBigEndian32(png, at);
        if (length > png.size() - at - 12) throw std::runtime_error(name + ": truncated PNG chunk at byte " + std::to_string(at));
        Chunk c{at, png.substr(at + 4, 4), png.substr(at + 8, length)};
        if (pngCrc(c.type + c.data) != readBigEndian32(png, at + 8 + length))
            throw std::runtime_error(name + ": PNG chunk " + c.type + " at byte " + std::to_string(at) + " has a wrong CRC");
        at += 12 + length;
        const bool end = c.type == "IEND";
        visit(c);
        if (end) return;
    }
}

} // namespace

std::uint32_t pngCrc(const std::string& bytes) {
    static const std::array<std::uint32_t, 256> table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t n = 0; n < 256; ++n) {
            std::uint32_t c = n;
            for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xedb88320u ^ (c >> 1) : c >> 1;
            t[n] = c;
        }
        return t;
    }();
    std::uint32_t crc = 0xffffffffu;
    for (char byte : bytes) crc = table[(crc ^ static_cast<unsigned char>(byte)) & 0xff] ^ (crc >> 8);
    return crc ^ 0xffffffffu;
}

std::string insertPngText(const std::string& png, const ImageMetadata& metadata) {
    std::size_t iend = std::string::npos;
    try {
        walkChunks(png, "PNG", [&](const Chunk& c) {
            if (c.type == "IEND") iend = c.start;
        });
    } catch (const std::runtime_error& e) {
        throw std::invalid_argument(e.what());
    }
    std::string chunks;
    for (const auto& [key, value] : metadata.entries) {
        if (key.empty() || key.size() > 79 || key.find('\0') != std::string::npos)
            throw std::invalid_argument("PNG text key \"" + key + "\" is not 1 to 79 characters without NUL");
        // keyword, NUL, compression flag 0, method 0, empty language tag, NUL, empty translated keyword, NUL, text
        chunks += chunk("iTXt", key + std::string("\0\0\0\0\0", 5) + value);
    }
    return png.substr(0, iend) + chunks + png.substr(iend);
}

ImageMetadata readPngText(const std::string& png, const std::string& sourceName) {
    ImageMetadata metadata;
    walkChunks(png, sourceName, [&](const Chunk& c) {
        if (c.type != "iTXt") return;
        const std::size_t keyEnd = c.data.find('\0');
        if (keyEnd == std::string::npos || c.data.size() < keyEnd + 3) return; // malformed: not ours
        if (c.data[keyEnd + 1] != 0) return;                                      // compressed: not ours
        const std::size_t languageEnd = c.data.find('\0', keyEnd + 3);
        const std::size_t translatedEnd = languageEnd == std::string::npos ? languageEnd : c.data.find('\0', languageEnd + 1);
        if (translatedEnd == std::string::npos) return;
        metadata.entries.emplace_back(c.data.substr(0, keyEnd), c.data.substr(translatedEnd + 1));
    });
    return metadata;
}

ImageMetadata readPngTextFile(const std::filesystem::path& path) {
    std::string bytes;
    try {
        bytes = readInputFile(path, 1024 * kMiB, "PNG image");
    } catch (const InputFileError& e) {
        throw std::runtime_error(e.what());
    }
    return readPngText(bytes, path.string());
}

} // namespace ptview
