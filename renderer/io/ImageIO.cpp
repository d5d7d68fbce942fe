#include <ptview/io/ImageIO.h>

#include <ptview/io/ExrIO.h>
#include <ptview/io/InputFile.h>
#include <ptview/io/PngText.h>

#include <stb_image_write.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <vector>
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
std::filesystem::path writeTarget(const std::filesystem::path& path) {
    // As the kernel resolves them: at most 40 links, each relative to the directory holding it.
    std::filesystem::path target = path;
    for (int hops = 0; hops < 40; ++hops) {
        std::error_code error;
        if (!std::filesystem::is_symlink(std::filesystem::symlink_status(target, error))) return target;
        const std::filesystem::path next = std::filesystem::read_symlink(target, error);
        if (error) fail(path, "cannot read the symbolic link: " + error.message());
        target = next.is_absolute() ? next : target.parent_path() / next;
    }
    fail(path, std::strerror(ELOOP));
}

std::filesystem::path temporaryPathFor(const std::filesystem::path& target) {
    std::filesystem::path temporary = target;
    temporary += ".tmp-" + std::to_string(::getpid());
    return temporary;
}

void reportFileSizeLimitAsWriteError() {
    std::signal(SIGXFSZ, SIG_IGN);
}

void writeFileAtomically(const std::filesystem::path& path, const std::string& bytes) {
    const std::filesystem::path target = writeTarget(path);
    const std::filesystem::path temporary = temporaryPathFor(target);
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
    std::filesystem::rename(temporary, target, error);
    if (error) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        fail(path, "cannot replace file: " + error.message());
    }
}

void writePng(const std::filesystem::path& path, const ImageRgba8& image, const ImageMetadata& metadata) {
    std::string bytes;
    if (!stbi_write_png_to_func(appendBytes, &bytes, image.width, image.height, 4, image.rgba.data(), image.width * 4))
        fail(path, "PNG encoding failed");
    if (!metadata.empty()) bytes = insertPngText(bytes, metadata);
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
    try {
        checkInputFile(path, "reference image"); // not a directory, a device or a FIFO
    } catch (const InputFileError& e) {
        throw std::runtime_error(e.what());
    }
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

    // The header alone must not decide how much memory is taken: a file of 20 bytes may claim
    // 65536 x 65536 pixels (48 GiB). The pixels are read a chunk at a time, so what is allocated
    // never runs more than a chunk (and the vector's growth) ahead of what the file holds.
    constexpr size_t kChunkFloats = size_t(1) << 20; // 4 MiB
    const size_t rowFloats = static_cast<size_t>(width) * 3;
    const size_t floatCount = rowFloats * static_cast<size_t>(height);
    std::vector<float> stored; // the rows as the file stores them, bottom to top
    while (stored.size() < floatCount) {
        const size_t offset = stored.size();
        const size_t count = std::min(kChunkFloats, floatCount - offset);
        stored.resize(offset + count);
        if (!in.read(reinterpret_cast<char*>(stored.data() + offset), static_cast<std::streamsize>(count * sizeof(float))))
            fail(path, "truncated PFM data (the header says " + std::to_string(width) + "x" + std::to_string(height) +
                           " pixels)");
    }
    for (size_t top = 0, bottom = static_cast<size_t>(height) - 1; top < bottom; ++top, --bottom)
        std::swap_ranges(stored.begin() + static_cast<std::ptrdiff_t>(top * rowFloats),
                         stored.begin() + static_cast<std::ptrdiff_t>((top + 1) * rowFloats),
                         stored.begin() + static_cast<std::ptrdiff_t>(bottom * rowFloats));
    ImageRgbF image;
    image.width = width;
    image.height = height;
    image.rgb = std::move(stored);
    return image;
}

bool hasExrExtension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    return extension == ".exr";
}

// The one place that decides how a linear image file is read: by its extension.
ImageRgbF readLinearImage(const std::filesystem::path& path) {
    if (hasExrExtension(path)) return exrRgb(readExr(path), path.string());
    return readPfm(path);
}

} // namespace ptview
