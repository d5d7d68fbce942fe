#include <ptview/io/InputFile.h>

#include <cerrno>
#include <cstring>
#include <new>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace ptview {
namespace {

std::string mebibytes(std::uintmax_t bytes) {
    return std::to_string((bytes + kMiB - 1) / kMiB) + " MiB";
}

const char* fileType(mode_t mode) {
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

// Closes the descriptor on every way out.
struct FileDescriptor {
    int fd = -1;
    ~FileDescriptor() {
        if (fd >= 0) ::close(fd);
    }
};

// Opens without blocking (a FIFO's open would otherwise wait for a writer) and refuses anything
// but a regular file; returns its size.
std::uintmax_t openRegularFile(const std::filesystem::path& path, const char* kind, FileDescriptor& file) {
    auto cannotOpen = [&](const std::string& reason) {
        return InputFileError(path.string() + ": cannot open " + kind + ": " + reason);
    };
    file.fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (file.fd < 0) throw cannotOpen(std::strerror(errno));
    struct stat status {};
    if (::fstat(file.fd, &status) != 0) throw cannotOpen(std::strerror(errno));
    if (S_ISDIR(status.st_mode)) throw cannotOpen(std::strerror(EISDIR));
    if (!S_ISREG(status.st_mode)) throw cannotOpen(std::string(fileType(status.st_mode)) + ", not a regular file");
    return static_cast<std::uintmax_t>(status.st_size);
}

} // namespace

std::string readInputFile(const std::filesystem::path& path, std::uintmax_t maxBytes, const char* kind) {
    FileDescriptor file;
    const std::uintmax_t size = openRegularFile(path, kind, file);
    auto tooLarge = [&](std::uintmax_t bytes) {
        return InputFileError(path.string() + ": " + kind + " too large (" + mebibytes(bytes) + "; at most " +
                              mebibytes(maxBytes) + ")");
    };
    if (size > maxBytes) throw tooLarge(size);
    std::string bytes;
    try {
        bytes.resize(static_cast<std::size_t>(size));
    } catch (const std::bad_alloc&) {
        throw InputFileError(path.string() + ": not enough memory to load it (" + std::to_string(size / kMiB) +
                             " MiB on disk)");
    }
    // A file that changes while it is read: what is there, still within the limit.
    std::size_t filled = 0;
    for (;;) {
        if (filled == bytes.size()) {
            if (bytes.size() > maxBytes) throw tooLarge(bytes.size());
            char probe[4096];
            const ::ssize_t n = ::read(file.fd, probe, sizeof probe);
            if (n < 0 && errno == EINTR) continue;
            if (n < 0) throw InputFileError(path.string() + ": cannot read " + kind + ": " + std::strerror(errno));
            if (n == 0) break;
            bytes.append(probe, static_cast<std::size_t>(n));
            filled = bytes.size();
            continue;
        }
        const ::ssize_t n = ::read(file.fd, bytes.data() + filled, bytes.size() - filled);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw InputFileError(path.string() + ": cannot read " + kind + ": " + std::strerror(errno));
        if (n == 0) {
            bytes.resize(filled); // the file shrank meanwhile
            break;
        }
        filled += static_cast<std::size_t>(n);
    }
    return bytes;
}

void checkInputFile(const std::filesystem::path& path, const char* kind) {
    FileDescriptor file;
    openRegularFile(path, kind, file);
}

} // namespace ptview
