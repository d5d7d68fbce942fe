#include <ptview/io/ExrIO.h>

#include <ptview/io/ImageIO.h>
#include <ptview/io/InputFile.h>

#include <ImfAttribute.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <Imath/half.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <limits>
#include <stdexcept>

namespace ptview {
namespace {

[[noreturn]] void fail(const std::string& name, const std::string& what) {
    throw std::runtime_error(name + ": " + what);
}

// OpenEXR trusts the sizes in a header: a string attribute is resized to the length it declares
// before it is read (what that cost: docs/performance.md, "Measurements behind code comments"), a
// preview image to the pixels it declares, a string vector's strings each to theirs; and a value of
// a fixed-size type is read at its own size whatever the header says, so a wrong size shifts where
// the library reads the next attribute from. This walks the header as the library will (OpenEXR
// file layout: magic, version, then per part "name\0type\0", a little-endian int32 size and the
// value, an empty name ending the part) and refuses, before the library sees the file, any size
// that disagrees with its type or declares more bytes than the file has left.
class ExrHeaderCheck {
public:
    ExrHeaderCheck(const std::string& bytes, const std::string& sourceName) : bytes_(bytes), source_(sourceName) {}

    void run() {
        constexpr std::uint32_t kMultiPart = 0x1000; // version flag: several headers, an empty one ends them
        if (bytes_.size() < 8 || bytes_.compare(0, 4, "\x76\x2f\x31\x01") != 0) return; // the library says what it is not
        at_ = 4;
        const std::uint32_t version = readU32();
        for (bool firstPart = true;; firstPart = false) {
            std::string name = readName();
            if (name.empty()) {
                if (firstPart || !(version & kMultiPart)) refuse("a header without attributes");
                return; // the empty header after the last part
            }
            for (; !name.empty(); name = readName()) {
                const std::string type = readName();
                const std::uint32_t size = readU32();
                checkValue(name, type, size);
            }
            if (!(version & kMultiPart)) return;
        }
    }

private:
    [[noreturn]] void refuse(const std::string& why) const { fail(source_, "not a readable EXR file: " + why); }
    std::size_t left() const { return bytes_.size() - at_; }

    std::string readName() {
        const std::size_t end = bytes_.find('\0', at_);
        if (end == std::string::npos) refuse("its header is cut short");
        std::string name = bytes_.substr(at_, end - at_);
        at_ = end + 1;
        return name;
    }
    std::uint32_t readU32() {
        if (left() < 4) refuse("its header is cut short");
        std::uint32_t value = 0;
        for (int i = 3; i >= 0; --i) value = value << 8 | static_cast<unsigned char>(bytes_[at_ + static_cast<std::size_t>(i)]);
        at_ += 4;
        return value;
    }

    void checkValue(const std::string& name, const std::string& type, std::uint32_t size) {
        auto wrong = [&](const std::string& what) {
            refuse("its header attribute \"" + name + "\" (" + type + ") " + what + " (truncated or corrupt EXR?)");
        };
        if (size > left())
            wrong("declares " + std::to_string(size) + " bytes, more than the " + std::to_string(left()) + " left in the file");
        const std::size_t valueStart = at_;
        at_ += size;
        static const std::map<std::string, std::uint32_t> kFixedSizes = {
            {"box2i", 16}, {"box2f", 16}, {"compression", 1}, {"lineOrder", 1}, {"envmap", 1}, {"deepImageState", 1},
            {"float", 4}, {"int", 4}, {"double", 8}, {"rational", 8}, {"v2i", 8}, {"v2f", 8}, {"v2d", 16}, {"v3i", 12},
            {"v3f", 12}, {"v3d", 24}, {"m33f", 36}, {"m33d", 72}, {"m44f", 64}, {"m44d", 128}, {"chromaticities", 32},
            {"keycode", 28}, {"timecode", 8}, {"tiledesc", 9}};
        if (auto fixed = kFixedSizes.find(type); fixed != kFixedSizes.end()) {
            if (size != fixed->second) wrong("declares " + std::to_string(size) + " bytes, not the " + std::to_string(fixed->second) + " of its type");
        } else if (type == "chlist") {
            // Channels until an empty name, each name then 16 bytes: the library reads them so.
            std::size_t p = valueStart;
            const std::size_t end = valueStart + size;
            for (;;) {
                const std::size_t nameEnd = bytes_.find('\0', p);
                if (nameEnd == std::string::npos || nameEnd >= end) wrong("runs past its declared size");
                if (nameEnd == p) break;
                p = nameEnd + 1 + 16;
                if (p > end) wrong("runs past its declared size");
            }
            if (p + 1 != end) wrong("does not end where its size says");
        } else if (type == "preview") {
            if (size < 8) wrong("is too short for a preview image");
            std::uint64_t width = 0, height = 0;
            for (int i = 3; i >= 0; --i) {
                width = width << 8 | static_cast<unsigned char>(bytes_[valueStart + static_cast<std::size_t>(i)]);
                height = height << 8 | static_cast<unsigned char>(bytes_[valueStart + 4 + static_cast<std::size_t>(i)]);
            }
            if (8 + 4 * width * height != size) wrong("declares a preview of " + std::to_string(width) + "x" + std::to_string(height) + " pixels that its size does not hold");
        } else if (type == "stringvector") {
            // Strings each with its int32 length, which the library allocates before reading.
            for (std::size_t p = valueStart; p < valueStart + size;) {
                if (valueStart + size - p < 4) wrong("runs past its declared size");
                std::uint32_t length = 0;
                for (int i = 3; i >= 0; --i) length = length << 8 | static_cast<unsigned char>(bytes_[p + static_cast<std::size_t>(i)]);
                p += 4;
                if (length > valueStart + size - p) wrong("holds a string longer than its declared size");
                p += length;
            }
        } else if (type != "string" && type != "floatvector" && Imf::Attribute::knownType(type.c_str())) {
            // A type the library knows and reads by a layout of its own (an ID manifest, with its
            // compressed size): not one ptview's images or references use.
            wrong("is of a type ptview does not read");
        }
        // string, floatvector and unknown (opaque) types: read at their declared size, checked above.
    }

    const std::string& bytes_;
    const std::string& source_;
    std::size_t at_ = 0;
};

// The library writes through Imf::OStream; this one collects the bytes so that writeFileAtomically
// can put them in place all at once.
class StringOStream : public Imf::OStream {
public:
    StringOStream() : Imf::OStream("memory") {}
    void write(const char c[], int n) override {
        if (position_ + static_cast<std::size_t>(n) > bytes_.size()) bytes_.resize(position_ + static_cast<std::size_t>(n));
        std::memcpy(&bytes_[position_], c, static_cast<std::size_t>(n));
        position_ += static_cast<std::size_t>(n);
    }
    uint64_t tellp() override { return position_; }
    void seekp(uint64_t position) override { position_ = static_cast<std::size_t>(position); }
    std::string& bytes() { return bytes_; }

private:
    std::string bytes_;
    std::size_t position_ = 0;
};

class StringIStream : public Imf::IStream {
public:
    StringIStream(const std::string& bytes, const std::string& name) : Imf::IStream(name.c_str()), bytes_(bytes) {}
    // As Imf::StdIFStream: throws past the end, returns whether bytes remain.
    bool read(char c[], int n) override {
        if (n < 0 || position_ + static_cast<std::size_t>(n) > bytes_.size())
            throw std::runtime_error("unexpected end of file (truncated EXR)");
        std::memcpy(c, bytes_.data() + position_, static_cast<std::size_t>(n));
        position_ += static_cast<std::size_t>(n);
        return position_ < bytes_.size();
    }
    uint64_t tellg() override { return position_; }
    void seekg(uint64_t position) override { position_ = static_cast<std::size_t>(std::min<uint64_t>(position, bytes_.size())); }

private:
    const std::string& bytes_;
    std::size_t position_ = 0;
};

} // namespace

const ExrChannel* ExrImage::find(const std::string& name) const {
    for (const ExrChannel& channel : channels)
        if (channel.name == name) return &channel;
    return nullptr;
}

void ExrImage::addComponent(const std::string& name, const ImageRgbF& image, int component) {
    ExrChannel channel{name, std::vector<float>(static_cast<std::size_t>(image.width) * image.height)};
    for (std::size_t i = 0; i < channel.values.size(); ++i) channel.values[i] = image.rgb[i * 3 + component];
    channels.push_back(std::move(channel));
}

void ExrImage::addRgb(const ImageRgbF& image, const std::string& prefix) {
    addComponent(prefix + "R", image, 0);
    addComponent(prefix + "G", image, 1);
    addComponent(prefix + "B", image, 2);
}

std::string encodeExr(const ExrImage& image, ExrPixelType type) {
    const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION; // lossless, read by every EXR tool
    for (const auto& [key, value] : image.metadata.entries) header.insert(key, Imf::StringAttribute(value));
    const Imf::PixelType pixelType = type == ExrPixelType::Half ? Imf::HALF : Imf::FLOAT;
    std::vector<std::vector<Imath::half>> halves(image.channels.size());
    Imf::FrameBuffer frameBuffer;
    for (std::size_t c = 0; c < image.channels.size(); ++c) {
        const ExrChannel& channel = image.channels[c];
        if (channel.values.size() != pixels) throw std::invalid_argument("EXR channel " + channel.name + " has the wrong size");
        header.channels().insert(channel.name, Imf::Channel(pixelType));
        if (type == ExrPixelType::Half) {
            halves[c].assign(channel.values.begin(), channel.values.end());
            frameBuffer.insert(channel.name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(halves[c].data()),
                                                        sizeof(Imath::half), sizeof(Imath::half) * image.width));
        } else {
            frameBuffer.insert(channel.name, Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(channel.values.data())),
                                                        sizeof(float), sizeof(float) * image.width));
        }
    }
    StringOStream stream;
    {
        Imf::OutputFile file(stream, header);
        file.setFrameBuffer(frameBuffer);
        file.writePixels(image.height);
    } // the destructor completes the file (the line offset table)
    return std::move(stream.bytes());
}

void writeExr(const std::filesystem::path& path, const ExrImage& image, ExrPixelType type) {
    std::string bytes;
    try {
        bytes = encodeExr(image, type);
    } catch (const std::exception& e) {
        fail(path.string(), std::string("EXR encoding failed: ") + e.what());
    }
    writeFileAtomically(path, bytes);
}

ExrImage decodeExr(const std::string& bytes, const std::string& sourceName) {
    ExrImage image;
    try {
        ExrHeaderCheck(bytes, sourceName).run();
        StringIStream stream(bytes, sourceName);
        Imf::InputFile file(stream);
        const Imath::Box2i window = file.header().dataWindow();
        const long long width = static_cast<long long>(window.max.x) - window.min.x + 1;
        const long long height = static_cast<long long>(window.max.y) - window.min.y + 1;
        if (width <= 0 || height <= 0 || width > 65536 || height > 65536)
            fail(sourceName, "bad EXR data window (" + std::to_string(width) + "x" + std::to_string(height) + ")");
        long long channelCount = 0;
        for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it) ++channelCount;
        // The header alone must not decide how much memory is taken: ZIP packs at most ~1032:1,
        // so a file claims no more floats than that many times its size (plus room for tiny files).
        const long long floats = width * height * channelCount;
        if (floats > 1100LL * static_cast<long long>(bytes.size()) + (1LL << 20))
            fail(sourceName, "the EXR header claims " + std::to_string(width) + "x" + std::to_string(height) + " pixels of " +
                                 std::to_string(channelCount) + " channels, more than a file of " +
                                 std::to_string(bytes.size()) + " bytes can hold (truncated EXR?)");
        image.width = static_cast<int>(width);
        image.height = static_cast<int>(height);
        Imf::FrameBuffer frameBuffer;
        for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it) {
            if (it.channel().xSampling != 1 || it.channel().ySampling != 1)
                fail(sourceName, std::string("EXR channel ") + it.name() + " is subsampled (not supported)");
            image.channels.push_back({it.name(), std::vector<float>(static_cast<std::size_t>(width * height))});
        }
        for (ExrChannel& channel : image.channels) {
            // The slice's origin is pixel (0, 0); the data window may start elsewhere.
            char* origin = reinterpret_cast<char*>(channel.values.data()) -
                           (static_cast<std::ptrdiff_t>(window.min.x) + static_cast<std::ptrdiff_t>(window.min.y) * width) *
                               static_cast<std::ptrdiff_t>(sizeof(float));
            frameBuffer.insert(channel.name, Imf::Slice(Imf::FLOAT, origin, sizeof(float), sizeof(float) * width));
        }
        file.setFrameBuffer(frameBuffer);
        file.readPixels(window.min.y, window.max.y);
        for (auto it = file.header().begin(); it != file.header().end(); ++it)
            if (const auto* text = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
                image.metadata.entries.emplace_back(it.name(), text->value());
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        if (what.rfind(sourceName + ":", 0) == 0) throw;
        fail(sourceName, "not a readable EXR file: " + what);
    } catch (const std::exception& e) { // Iex::BaseExc and the library's other failures
        fail(sourceName, std::string("not a readable EXR file: ") + e.what());
    }
    return image;
}

ExrImage readExr(const std::filesystem::path& path) {
    std::string bytes;
    try {
        bytes = readInputFile(path, 4096 * kMiB, "EXR image");
    } catch (const InputFileError& e) {
        throw std::runtime_error(e.what());
    }
    return decodeExr(bytes, path.string());
}

ImageRgbF exrRgb(const ExrImage& image, const std::string& sourceName) {
    ImageRgbF rgb(image.width, image.height);
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
        const ExrChannel* channel = image.find(names[c]);
        if (!channel) fail(sourceName, std::string("the EXR file has no ") + names[c] + " channel");
        for (std::size_t i = 0; i < channel->values.size(); ++i) rgb.rgb[i * 3 + c] = channel->values[i];
    }
    return rgb;
}

} // namespace ptview
