#include "ImageIO.h"

#include <stb_image_write.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace ptview {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
    throw std::runtime_error(path.string() + ": " + what);
}

void appendBytes(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<size_t>(size));
}

} // namespace

void writeFileAtomically(const std::filesystem::path& path, const std::string& bytes) {
    std::filesystem::path temporary = path;
    temporary += ".tmp-" + std::to_string(::getpid());
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) fail(path, std::string("cannot write: ") + std::strerror(errno));
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.flush();
        if (!out) {
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);
            fail(path, "write failed (disk full?)");
        }
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        fail(path, "cannot replace file: " + error.message());
    }
}

void writePng(const std::filesystem::path& path, const ImageRgba8& image) {
    std::string bytes;
    if (!stbi_write_png_to_func(appendBytes, &bytes, image.width, image.height, 4, image.rgba.data(), image.width * 4))
        fail(path, "PNG encoding failed");
    writeFileAtomically(path, bytes);
}

void writePfm(const std::filesystem::path& path, const ImageRgbF& image) {
    // A negative scale marks little-endian data.
    std::string bytes = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
    size_t rowBytes = static_cast<size_t>(image.width) * 3 * sizeof(float);
    for (int y = image.height - 1; y >= 0; --y)
        bytes.append(reinterpret_cast<const char*>(image.rgb.data() + static_cast<size_t>(y) * image.width * 3), rowBytes);
    writeFileAtomically(path, bytes);
}

ImageRgbF readPfm(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, std::string("cannot open: ") + std::strerror(errno));
    std::string magic;
    int width = 0, height = 0;
    double scale = 0.0;
    in >> magic >> width >> height >> scale;
    if (!in || magic != "PF") fail(path, "not a colour PFM file (expected header \"PF\")");
    if (width <= 0 || height <= 0 || width > 65536 || height > 65536) fail(path, "bad PFM size");
    if (scale >= 0.0) fail(path, "big-endian PFM is not supported");
    in.get(); // the single whitespace byte that ends the header
    ImageRgbF image(width, height);
    size_t rowFloats = static_cast<size_t>(width) * 3;
    for (int y = height - 1; y >= 0; --y)
        in.read(reinterpret_cast<char*>(image.rgb.data() + static_cast<size_t>(y) * rowFloats),
                static_cast<std::streamsize>(rowFloats * sizeof(float)));
    if (!in) fail(path, "truncated PFM data");
    return image;
}

} // namespace ptview
