#include <ptview/scene/EnvironmentMap.h>

#include <ptview/io/InputFile.h>
#include <ptview/scene/SceneRanges.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
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
// Decoded here rather than by stb_image, which trusts the data (at the end of the file its reader
// returns zeros, and a run of length 0 makes its RLE loop spin forever) and refuses any image of
// more than 2^31 bytes as floats ("too large": 16384x16384 is 3 GiB). The layout read is stb's:
// scanlines of new-style RLE (2, 2, width) with each channel run-length coded, or flat RGBE
// pixels, into which a scanline that does not start with an RLE marker turns the whole image from
// its first pixel on. Anything incomplete or corrupt is refused naming the scanline.

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

    // Whether what follows the header can hold pixel data of this size at all: the fewest bytes
    // it can take (every scanline run-length coded in runs of the longest, 127, or flat pixels,
    // whichever is shorter). Only then is room for all the texels taken at once, so that a short
    // file cannot claim gigabytes; otherwise they grow as scanlines are decoded, until the data
    // is found cut short or corrupt at its place.
    bool canHoldPixels(const RadianceHeader& header) const {
        const std::size_t width = static_cast<std::size_t>(header.width);
        const std::size_t height = static_cast<std::size_t>(header.height);
        std::size_t least = 4 * width * height;
        if (width >= 8 && width < 32768) least = std::min(least, height * (4 + 4 * 2 * ((width + 126) / 127)));
        return bytes_.size() - at_ >= least;
    }

    // Linear radiance, 3 floats per texel, row 0 the top, into `rgb`.
    void decodePixels(const RadianceHeader& header, std::vector<float>& rgb) {
        const std::size_t width = static_cast<std::size_t>(header.width);
        const std::size_t height = static_cast<std::size_t>(header.height);
        if (width < 8 || width >= 32768) return decodeFlat(width * height, rgb);
        std::vector<unsigned char> scanline(width * 4);
        for (std::size_t row = 0; row < height; ++row) {
            std::size_t rowStart = at_;
            needInScanline(4, row);
            auto b = [&](std::size_t k) { return static_cast<unsigned char>(bytes_[rowStart + k]); };
            if (b(0) != 2 || b(1) != 2 || (b(2) & 0x80)) {
                at_ = rowStart;
                return decodeFlat(width * height, rgb);
            }
            at_ += 4;
            std::size_t length = (std::size_t(b(2)) << 8) | b(3);
            if (length != width)
                fail("corrupt scanline " + std::to_string(row) + " (length " + std::to_string(length) +
                     ", expected " + std::to_string(width) + ")");
            for (int channel = 0; channel < 4; ++channel) {
                std::size_t filled = 0;
                while (filled < width) {
                    needInScanline(1, row);
                    unsigned count = static_cast<unsigned char>(bytes_[at_++]);
                    bool isRun = count > 128;
                    if (isRun) count -= 128;
                    if (count == 0 || count > width - filled)
                        fail("corrupt run-length data in scanline " + std::to_string(row));
                    needInScanline(isRun ? 1 : count, row);
                    for (unsigned k = 0; k < count; ++k, ++filled)
                        scanline[filled * 4 + channel] = static_cast<unsigned char>(bytes_[isRun ? at_ : at_ + k]);
                    at_ += isRun ? 1 : count;
                }
            }
            rgb.resize((row + 1) * width * 3);
            for (std::size_t i = 0; i < width; ++i) convert(&scanline[i * 4], &rgb[(row * width + i) * 3]);
        }
    }

private:
    void decodeFlat(std::size_t texels, std::vector<float>& rgb) {
        need(4 * texels, "pixel data");
        rgb.resize(3 * texels);
        const auto* data = reinterpret_cast<const unsigned char*>(bytes_.data() + at_);
        for (std::size_t t = 0; t < texels; ++t) convert(data + 4 * t, &rgb[3 * t]);
        at_ += 4 * texels;
    }

    // RGBE: three mantissas sharing the exponent e, each worth m * 2^(e - 136); e = 0 is black.
    static void convert(const unsigned char* rgbe, float* out) {
        const float scale = rgbe[3] != 0 ? std::ldexp(1.0f, int(rgbe[3]) - (128 + 8)) : 0.0f;
        for (int c = 0; c < 3; ++c) out[c] = float(rgbe[c]) * scale;
    }

    // The next line without its '\n'; at the end of the data, what is left.
    std::string line() {
        std::size_t end = bytes_.find('\n', at_);
        if (end == std::string::npos) end = bytes_.size();
        std::string text = bytes_.substr(at_, end - at_);
        at_ = std::min(end + 1, bytes_.size());
        return text;
    }

    // The message is built only on failure: this runs for every run of every scanline.
    void needInScanline(std::size_t count, std::size_t row) {
        if (bytes_.size() - at_ < count) need(count, "scanline " + std::to_string(row));
    }

    void need(std::size_t count, const std::string& what) {
        if (bytes_.size() - at_ < count) fail("truncated (the file ends inside " + what + ")");
    }

    [[noreturn]] void fail(const std::string& reason) const { throw EnvironmentMapError(file_ + ": " + reason); }

    const std::string& bytes_;
    const std::string& file_;
    std::size_t at_ = 0;
};

// A flat (uncompressed) map of the largest size, and room for its header.
constexpr std::uintmax_t kMaxHdrFileBytes =
    4 * std::uintmax_t(kMaxEnvironmentMapSize) * std::uintmax_t(kMaxEnvironmentMapSize) + kMiB;

std::string mebibytes(std::size_t bytes) {
    return std::to_string((bytes + kMiB - 1) / kMiB) + " MiB";
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
        // Bounded like every radiance of the scene format: times an environment intensity within
        // its range (also at most kMaxSceneRadiance) the product stays finite in float.
        if (rgb[k] >= 0.0f && rgb[k] <= kMaxSceneRadiance) continue; // false for NaN
        std::size_t texel = k / 3;
        char value[32];
        std::snprintf(value, sizeof value, "%g", double(rgb[k]));
        fail("texel (" + std::to_string(texel % w) + ", " + std::to_string(texel / w) + ") has radiance " + value +
             " (expected a number in [0, 1e9])");
    }

    EnvironmentMap map;
    map.source = sourceName;
    map.width = width;
    map.height = height;
    map.rgb = std::move(rgb);
    try {
        map.conditionalCdf.reserve(w * h);
        map.marginalCdf.reserve(h);
    } catch (const std::bad_alloc&) {
        fail("not enough memory for the sampling distribution of its " + std::to_string(width) + "x" +
             std::to_string(height) + " texels (" + mebibytes((w * h + h) * sizeof(float)) + ")");
    }

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
    std::string bytes = readInputFileAs<EnvironmentMapError>(path, kMaxHdrFileBytes, "environment map");
    RadianceReader reader(bytes, file);
    RadianceHeader header = reader.readHeader();
    const std::size_t floats = std::size_t(header.width) * std::size_t(header.height) * 3;
    std::vector<float> rgb;
    try {
        if (reader.canHoldPixels(header)) rgb.reserve(floats);
        reader.decodePixels(header, rgb);
    } catch (const std::bad_alloc&) {
        throw EnvironmentMapError(file + ": not enough memory for its " + std::to_string(header.width) + "x" +
                                  std::to_string(header.height) + " texels (" + mebibytes(floats * sizeof(float)) + ")");
    }
    bytes = std::string(); // the file's bytes are not needed while the distribution is built
    return makeEnvironmentMap(header.width, header.height, std::move(rgb), file);
}

} // namespace ptview
