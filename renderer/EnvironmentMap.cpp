#include "EnvironmentMap.h"

#include <stb_image.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <system_error>
#include <utility>

namespace ptview {
namespace {

double luminance(const float* rgb) {
    return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

// --- Radiance RGBE files ----------------------------------------------------------------------
//
// stb_image decodes them, but trusts the data: at the end of the file its reader returns zeros,
// and a run of length 0 makes its RLE loop spin forever (a truncated file hangs the program), while
// a truncated flat file decodes as black. So the structure is walked here first, the way stb
// reads it, and anything incomplete is refused before stb sees it.

struct RadianceHeader {
    int width = 0;
    int height = 0;
    std::size_t dataOffset = 0; // first byte after the resolution line
};

class RadianceReader {
public:
    RadianceReader(const std::string& bytes, const std::string& file) : bytes_(bytes), file_(file) {}

    RadianceHeader readHeader() {
        std::string magic = line();
        if (magic != "#?RADIANCE" && magic != "#?RGBE")
            fail("not a Radiance .hdr image (it must start with \"#?RADIANCE\")");
        bool rgbe = false;
        for (;;) {
            if (at_ >= bytes_.size()) fail("truncated header (no blank line before the resolution)");
            std::string text = line();
            if (text.empty()) break;
            if (text == "FORMAT=32-bit_rle_rgbe") rgbe = true;
        }
        if (!rgbe) fail("unsupported pixel format (only FORMAT=32-bit_rle_rgbe is read)");
        std::string resolution = line();
        // The standard orientation only: rows top to bottom, pixels left to right.
        const char* text = resolution.c_str();
        char* end = nullptr;
        RadianceHeader header;
        if (std::strncmp(text, "-Y ", 3) == 0) {
            long height = std::strtol(text + 3, &end, 10);
            while (*end == ' ') ++end;
            if (std::strncmp(end, "+X ", 3) == 0) {
                long width = std::strtol(end + 3, &end, 10);
                if (height >= 1 && width >= 1 && *end == '\0') {
                    if (width > kMaxEnvironmentMapSize || height > kMaxEnvironmentMapSize)
                        fail("is " + std::to_string(width) + "x" + std::to_string(height) + ", larger than " +
                             std::to_string(kMaxEnvironmentMapSize) + " on a side (the OpenGL 4.1 texture limit)");
                    header.width = static_cast<int>(width);
                    header.height = static_cast<int>(height);
                }
            }
        }
        if (header.width == 0)
            fail("unsupported resolution line \"" + resolution + "\" (expected \"-Y <height> +X <width>\")");
        header.dataOffset = at_;
        return header;
    }

    // Follows stb_image's decoder over the pixel data without decoding it.
    void checkPixels(const RadianceHeader& header) {
        const std::size_t width = static_cast<std::size_t>(header.width);
        const std::size_t height = static_cast<std::size_t>(header.height);
        if (width < 8 || width >= 32768) return need(4 * width * height, "pixel data");
        for (std::size_t row = 0; row < height; ++row) {
            std::size_t rowStart = at_;
            need(4, "scanline " + std::to_string(row));
            auto b = [&](std::size_t k) { return static_cast<unsigned char>(bytes_[rowStart + k]); };
            if (b(0) != 2 || b(1) != 2 || (b(2) & 0x80)) {
                // A flat scanline: stb then reads the whole image flat from here.
                at_ = rowStart;
                return need(4 * width * height, "pixel data");
            }
            at_ += 4;
            std::size_t length = (std::size_t(b(2)) << 8) | b(3);
            if (length != width)
                fail("corrupt scanline " + std::to_string(row) + " (length " + std::to_string(length) +
                     ", expected " + std::to_string(width) + ")");
            for (int channel = 0; channel < 4; ++channel) {
                std::size_t filled = 0;
                while (filled < width) {
                    need(1, "scanline " + std::to_string(row));
                    unsigned count = static_cast<unsigned char>(bytes_[at_++]);
                    bool isRun = count > 128;
                    if (isRun) count -= 128;
                    if (count == 0 || count > width - filled)
                        fail("corrupt run-length data in scanline " + std::to_string(row));
                    std::size_t payload = isRun ? 1 : count;
                    need(payload, "scanline " + std::to_string(row));
                    at_ += payload;
                    filled += count;
                }
            }
        }
    }

private:
    // The next line without its '\n'; at the end of the data, what is left.
    std::string line() {
        std::size_t end = bytes_.find('\n', at_);
        if (end == std::string::npos) end = bytes_.size();
        std::string text = bytes_.substr(at_, end - at_);
        at_ = std::min(end + 1, bytes_.size());
        return text;
    }

    void need(std::size_t count, const std::string& what) {
        if (bytes_.size() - at_ < count) fail("truncated (the file ends inside " + what + ")");
    }

    [[noreturn]] void fail(const std::string& reason) const { throw EnvironmentMapError(file_ + ": " + reason); }

    const std::string& bytes_;
    const std::string& file_;
    std::size_t at_ = 0;
};

std::string readFile(const std::filesystem::path& path) {
    auto cannotOpen = [&path](int error) {
        return EnvironmentMapError(path.string() + ": cannot open environment map: " + std::strerror(error));
    };
    std::error_code ignored;
    if (std::filesystem::is_directory(path, ignored)) throw cannotOpen(EISDIR);
    std::ifstream file(path, std::ios::binary);
    if (!file) throw cannotOpen(errno);
    std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    if (file.bad()) throw cannotOpen(errno);
    return bytes;
}

// Running sums in double, stored as float: a texel of weight 0 repeats the previous value
// exactly, and the last entry is set to exactly 1 so that every u in [0, 1) finds an entry above it.
void appendCdf(const double* weights, std::size_t count, std::vector<float>& out) {
    double total = 0.0;
    for (std::size_t i = 0; i < count; ++i) total += weights[i];
    double running = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        running += total > 0.0 ? weights[i] : 1.0;
        out.push_back(static_cast<float>(running / (total > 0.0 ? total : double(count))));
    }
    out.back() = 1.0f;
}

} // namespace

EnvironmentMap makeEnvironmentMap(int width, int height, std::vector<float> rgb, const std::string& sourceName) {
    auto fail = [&sourceName](const std::string& reason) { throw EnvironmentMapError(sourceName + ": " + reason); };
    if (width < 1 || height < 1) fail("empty image");
    if (width > kMaxEnvironmentMapSize || height > kMaxEnvironmentMapSize)
        fail("is " + std::to_string(width) + "x" + std::to_string(height) + ", larger than " +
             std::to_string(kMaxEnvironmentMapSize) + " on a side (the OpenGL 4.1 texture limit)");
    const std::size_t w = static_cast<std::size_t>(width), h = static_cast<std::size_t>(height);
    if (rgb.size() != w * h * 3) fail("expected " + std::to_string(w * h * 3) + " floats of radiance");
    for (std::size_t k = 0; k < rgb.size(); ++k) {
        if (std::isfinite(rgb[k]) && rgb[k] >= 0.0f) continue;
        std::size_t texel = k / 3;
        fail("texel (" + std::to_string(texel % w) + ", " + std::to_string(texel / w) + ") has radiance " +
             std::to_string(rgb[k]) + " (expected a finite number >= 0)");
    }

    EnvironmentMap map;
    map.source = sourceName;
    map.width = width;
    map.height = height;
    map.rgb = std::move(rgb);
    map.conditionalCdf.reserve(w * h);
    map.marginalCdf.reserve(h);

    const double pi = glm::pi<double>();
    std::vector<double> weights(w), rowWeights(h);
    glm::dvec3 radianceTimesSolidAngle(0.0);
    for (std::size_t j = 0; j < h; ++j) {
        double sinTheta = std::sin(pi * (double(j) + 0.5) / double(h));
        // Exact solid angle of one texel of this row: dphi * (cos theta_top - cos theta_bottom).
        double texelSolidAngle = 2.0 * pi / double(w) * (std::cos(pi * double(j) / double(h)) - std::cos(pi * double(j + 1) / double(h)));
        double rowSum = 0.0;
        for (std::size_t i = 0; i < w; ++i) {
            const float* texel = &map.rgb[(j * w + i) * 3];
            weights[i] = luminance(texel) * sinTheta;
            rowSum += weights[i];
            radianceTimesSolidAngle += glm::dvec3(texel[0], texel[1], texel[2]) * texelSolidAngle;
        }
        rowWeights[j] = rowSum;
        appendCdf(weights.data(), w, map.conditionalCdf);
    }
    appendCdf(rowWeights.data(), h, map.marginalCdf);
    map.meanRadiance = radianceTimesSolidAngle / (4.0 * pi);
    return map;
}

EnvironmentMap loadEnvironmentMap(const std::filesystem::path& path) {
    const std::string file = path.string();
    std::string bytes = readFile(path);
    RadianceReader reader(bytes, file);
    RadianceHeader header = reader.readHeader();
    reader.checkPixels(header);

    int width = 0, height = 0, channels = 0;
    std::unique_ptr<float, void (*)(void*)> pixels(
        stbi_loadf_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), static_cast<int>(bytes.size()), &width,
                               &height, &channels, 3),
        stbi_image_free);
    if (!pixels) throw EnvironmentMapError(file + ": cannot decode: " + stbi_failure_reason());
    if (width != header.width || height != header.height)
        throw EnvironmentMapError(file + ": decoded size differs from the header's");
    const float* begin = pixels.get();
    std::vector<float> rgb(begin, begin + std::size_t(width) * std::size_t(height) * 3);
    return makeEnvironmentMap(width, height, std::move(rgb), file);
}

} // namespace ptview
