#pragma once
// A PNG whose header claims a size its few bytes do not hold: what a hostile sender's texture
// looks like to a loader that trusts the header (a real 16384 x 16384 image compresses to about a
// megabyte; this one is 100 bytes). Its chunks and CRCs are well formed, so only decoding the
// pixels would find it short; a loader that checks the size first never gets there.
#include <cstdint>
#include <string>

namespace ptview::testing {

inline std::uint32_t pngCrc(const std::string& bytes) {
    std::uint32_t crc = 0xFFFFFFFFu;
    for (unsigned char byte : bytes) {
        crc ^= byte;
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return crc ^ 0xFFFFFFFFu;
}

inline std::string bigEndian32(std::uint32_t value) {
    return {static_cast<char>(value >> 24), static_cast<char>(value >> 16), static_cast<char>(value >> 8),
            static_cast<char>(value)};
}

inline std::string pngChunk(const std::string& kind, const std::string& data) {
    return bigEndian32(static_cast<std::uint32_t>(data.size())) + kind + data + bigEndian32(pngCrc(kind + data));
}

// RGBA, 8 bits, `width` x `height` in the header; the pixel data one zlib stored block of one
// row's filter byte.
inline std::string pngClaimingSize(std::uint32_t width, std::uint32_t height) {
    const std::string header = bigEndian32(width) + bigEndian32(height) + std::string("\x08\x06\x00\x00\x00", 5);
    const std::string zlib = std::string("\x78\x01\x01\x01\x00\xfe\xff\x00\x00\x01\x00\x01", 12); // adler32 of "\0"
    return std::string("\x89PNG\r\n\x1a\n", 8) + pngChunk("IHDR", header) + pngChunk("IDAT", zlib) + pngChunk("IEND", "");
}

} // namespace ptview::testing
