#pragma once
// An EXR header reader written from the file-format document (openexr.com, "The OpenEXR File
// Layout"), independent of the OpenEXR library: the magic number, the version field, then
// attributes (name NUL, type NUL, int32 size, value) up to an empty name. It decodes the attributes
// the tests check: channels (chlist), compression, dataWindow and strings.
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace ptview::testing {

struct ParsedExrChannel {
    std::string name;
    int pixelType = -1; // 0 uint, 1 half, 2 float
    int xSampling = 0, ySampling = 0;
};

struct ParsedExrHeader {
    bool ok = false;
    std::string error;
    int version = 0;
    std::uint32_t flags = 0;
    std::vector<ParsedExrChannel> channels;
    int compression = -1; // 0 none, 1 RLE, 2 ZIPS, 3 ZIP, 4 PIZ, ...
    int dataWindow[4] = {0, 0, -1, -1}; // xMin, yMin, xMax, yMax
    std::map<std::string, std::string> types;   // attribute name -> type name
    std::map<std::string, std::string> strings; // string attributes
};

inline std::int32_t littleEndian32(const std::string& bytes, std::size_t at) {
    std::uint32_t value = 0;
    for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(i)]);
    std::int32_t signedValue;
    std::memcpy(&signedValue, &value, 4);
    return signedValue;
}

inline ParsedExrHeader parseExrHeader(const std::string& bytes) {
    ParsedExrHeader header;
    auto fail = [&](const std::string& why) {
        header.error = why;
        return header;
    };
    if (bytes.size() < 8 || littleEndian32(bytes, 0) != 20000630) return fail("no EXR magic number");
    const std::uint32_t versionField = static_cast<std::uint32_t>(littleEndian32(bytes, 4));
    header.version = static_cast<int>(versionField & 0xff);
    header.flags = versionField & ~0xffu;
    std::size_t at = 8;
    auto readName = [&](std::string& name) {
        const std::size_t end = bytes.find('\0', at);
        if (end == std::string::npos) return false;
        name = bytes.substr(at, end - at);
        at = end + 1;
        return true;
    };
    while (true) {
        std::string name, type;
        if (!readName(name)) return fail("unterminated attribute name");
        if (name.empty()) break; // the end of the header
        if (!readName(type) || at + 4 > bytes.size()) return fail("truncated attribute " + name);
        const std::int32_t size = littleEndian32(bytes, at);
        at += 4;
        if (size < 0 || at + static_cast<std::size_t>(size) > bytes.size()) return fail("attribute " + name + " overruns the file");
        const std::string value = bytes.substr(at, static_cast<std::size_t>(size));
        at += static_cast<std::size_t>(size);
        header.types[name] = type;
        if (type == "string") header.strings[name] = value;
        if (type == "compression" && size == 1) header.compression = static_cast<unsigned char>(value[0]);
        if (type == "box2i" && name == "dataWindow" && size == 16)
            for (int i = 0; i < 4; ++i) header.dataWindow[i] = littleEndian32(value, static_cast<std::size_t>(i) * 4);
        if (type == "chlist") {
            std::size_t c = 0;
            while (c < value.size() && value[c] != '\0') {
                const std::size_t end = value.find('\0', c);
                if (end == std::string::npos || end + 17 > value.size()) return fail("bad chlist");
                ParsedExrChannel channel;
                channel.name = value.substr(c, end - c);
                channel.pixelType = littleEndian32(value, end + 1);
                // then pLinear (1 byte) and 3 reserved bytes
                channel.xSampling = littleEndian32(value, end + 9);
                channel.ySampling = littleEndian32(value, end + 13);
                header.channels.push_back(channel);
                c = end + 17;
            }
        }
    }
    header.ok = true;
    return header;
}

} // namespace ptview::testing
