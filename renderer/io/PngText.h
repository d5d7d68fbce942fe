#pragma once
// Text in PNG files: iTXt chunks (PNG 1.2, section 4.2.3.3), one per metadata entry, uncompressed
// UTF-8. stb writes the image; insertPngText adds the chunks before IEND with their CRCs.

#include <ptview/io/ImageMetadata.h>

#include <cstdint>
#include <filesystem>
#include <string>

namespace ptview {

// The PNG's bytes with an iTXt chunk per entry just before IEND. Keys must be 1 to 79 Latin-1
// characters without NUL (the PNG keyword rule): std::invalid_argument otherwise, as for bytes
// that are not a PNG.
std::string insertPngText(const std::string& png, const ImageMetadata& metadata);
// The uncompressed iTXt chunks of a PNG, in file order. Throws std::runtime_error naming
// sourceName for bytes that are not a PNG, a truncated chunk or a chunk whose CRC is wrong.
ImageMetadata readPngText(const std::string& png, const std::string& sourceName);
ImageMetadata readPngTextFile(const std::filesystem::path& path);

// CRC-32 as PNG defines it (ISO 3309 / ITU-T V.42, reflected, initial and final ~0).
std::uint32_t pngCrc(const std::string& bytes);

} // namespace ptview
