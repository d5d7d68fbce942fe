#pragma once
// OpenEXR files (through the OpenEXR library): scan-line images of named float channels, ZIP
// compressed, with string attributes in the header. Writes are atomic, as in ImageIO.h.

#include <ptview/io/Image.h>
#include <ptview/io/ImageMetadata.h>

#include <filesystem>
#include <string>
#include <vector>

namespace ptview {

enum class ExrPixelType { Half, Float };

// One channel: width x height floats, row 0 at the top. Names follow the EXR conventions: "R",
// "G", "B" for the image; "layer.R" for a layer; "Z" for depth.
struct ExrChannel {
    std::string name;
    std::vector<float> values;
};

struct ExrImage {
    int width = 0;
    int height = 0;
    std::vector<ExrChannel> channels;
    ImageMetadata metadata; // the header's string attributes (others are not read)

    const ExrChannel* find(const std::string& name) const;
    // Adds the three channels prefix + "R", "G", "B" (prefix "" or e.g. "albedo.").
    void addRgb(const ImageRgbF& image, const std::string& prefix = "");
    // Adds one channel of a single component (0, 1 or 2) of an RGB image.
    void addComponent(const std::string& name, const ImageRgbF& image, int component);
};

// Throws std::runtime_error naming the file. Every channel is stored as `type`; the channels must
// each hold width x height values.
void writeExr(const std::filesystem::path& path, const ExrImage& image, ExrPixelType type);
// The file's bytes, as writeExr would write them.
std::string encodeExr(const ExrImage& image, ExrPixelType type);

// Reads every channel as float (half, float and uint channels; any compression the library knows)
// and the string attributes. Throws std::runtime_error naming the file (`sourceName` for bytes).
ExrImage readExr(const std::filesystem::path& path);
ExrImage decodeExr(const std::string& bytes, const std::string& sourceName);

// The R, G and B channels as an image. Throws std::runtime_error naming `sourceName` when one is missing.
ImageRgbF exrRgb(const ExrImage& image, const std::string& sourceName);

} // namespace ptview
