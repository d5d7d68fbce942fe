#pragma once
// Image files. Writers never leave a partial file behind: they write a temporary file beside the
// target and rename it over the target only once it is complete.

#include <ptview/io/Image.h>
#include <ptview/io/ImageMetadata.h>

#include <filesystem>
#include <string>

namespace ptview {

// Throws std::runtime_error naming the file. A path that is a symbolic link is written through:
// the file it names is replaced (atomically, beside it), and the link stays.
void writeFileAtomically(const std::filesystem::path& path, const std::string& bytes);
// The file writeFileAtomically replaces for `path`: `path` itself, or what its chain of symbolic
// links ends at (which need not exist yet). Throws std::runtime_error naming the path for a loop.
std::filesystem::path writeTarget(const std::filesystem::path& path);
// The temporary file writeFileAtomically writes beside `target` before renaming it.
std::filesystem::path temporaryPathFor(const std::filesystem::path& target);
// Makes a write past the file-size limit (`ulimit -f`) fail with EFBIG, which writeFileAtomically
// reports as a write error, instead of SIGXFSZ killing the process with a temporary left behind.
// Called once at start-up, by main.
void reportFileSizeLimitAsWriteError();
// With metadata, each entry goes into an iTXt chunk (PngText.h).
void writePng(const std::filesystem::path& path, const ImageRgba8& image, const ImageMetadata& metadata = {});
// Portable float map: little-endian, rows stored bottom-to-top as the format defines.
void writePfm(const std::filesystem::path& path, const ImageRgbF& image);
ImageRgbF readPfm(const std::filesystem::path& path);
// A linear RGB image: an .exr (its R, G, B channels, ExrIO.h) or else a PFM. Throws as those do.
ImageRgbF readLinearImage(const std::filesystem::path& path);
bool hasExrExtension(const std::filesystem::path& path);

} // namespace ptview
