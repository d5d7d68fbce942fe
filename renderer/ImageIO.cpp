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
#include <fcntl.h>
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

// The bytes go to a temporary file beside the target, are flushed to the disk (fsync), and only
// then renamed over the target: rename within a directory is atomic, so a reader, a crash or a
// full disk sees either the old file or the whole new one, never a truncated mix. The temporary
// name carries the process id so that two ptview processes writing one path do not share it.
void writeFileAtomically(const std::filesystem::path& path, const std::string& bytes) {
    std::filesystem::path temporary = path;
    temporary += ".tmp-" + std::to_string(::getpid());
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) fail(path, std::string("cannot write: ") + std::strerror(errno));
    auto abandon = [&](const std::string& why) {
        ::close(fd);
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        fail(path, why);
    };
    for (std::size_t written = 0; written < bytes.size();) {
        const ::ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) abandon(std::string("write failed: ") + std::strerror(n < 0 ? errno : EIO));
        written += static_cast<std::size_t>(n);
    }
    if (::fsync(fd) != 0) abandon(std::string("write failed: ") + std::strerror(errno));
    if (::close(fd) != 0) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        fail(path, std::string("write failed: ") + std::strerror(errno));
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
