#pragma once
// Image files. Writers never leave a partial file behind: they write a temporary file beside the
// target and rename it over the target only once it is complete.

#include "Image.h"

#include <filesystem>
#include <string>

namespace ptview {

// Throws std::runtime_error naming the file.
void writeFileAtomically(const std::filesystem::path& path, const std::string& bytes);
void writePng(const std::filesystem::path& path, const ImageRgba8& image);
// Portable float map: little-endian, rows stored bottom-to-top as the format defines.
void writePfm(const std::filesystem::path& path, const ImageRgbF& image);
ImageRgbF readPfm(const std::filesystem::path& path);

} // namespace ptview
