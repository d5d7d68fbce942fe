#include <ptview/io/ImageDecode.h>

#include <stb_image.h>

#include <cstring>
#include <memory>
#include <new>

namespace ptview {

ImageRgba8 decodeImageRgba8(const std::string& bytes, const std::string& source) {
    auto fail = [&source](const std::string& reason) { return ImageDecodeError(source + ": " + reason); };
    if (bytes.empty()) throw fail("empty image file");
    if (bytes.size() > std::size_t(0x7fffffff)) throw fail("image too large to decode");
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int length = static_cast<int>(bytes.size());
    int width = 0, height = 0, channels = 0;
    // The header first, so a huge declared size is refused before any pixel memory is asked for.
    if (!stbi_info_from_memory(data, length, &width, &height, &channels))
        throw fail(std::string("cannot decode image (not a PNG or JPEG, or corrupt: ") + stbi_failure_reason() + ")");
    if (width < 1 || height < 1) throw fail("empty image");
    if (width > kMaxDecodedImageSize || height > kMaxDecodedImageSize)
        throw fail("image too large (" + std::to_string(width) + "x" + std::to_string(height) + "; at most " +
                   std::to_string(kMaxDecodedImageSize) + " on a side)");
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load_from_memory(data, length, &width, &height, &channels, 4),
                                                     stbi_image_free);
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        if (reason && std::strcmp(reason, "outofmem") == 0) throw fail("not enough memory to decode the image");
        throw fail(std::string("cannot decode image (") + (reason ? reason : "unknown error") + ")");
    }
    ImageRgba8 image;
    image.width = width;
    image.height = height;
    const std::size_t size = std::size_t(width) * std::size_t(height) * 4;
    try {
        image.rgba.assign(pixels.get(), pixels.get() + size);
    } catch (const std::bad_alloc&) {
        throw fail("not enough memory to decode the image");
    }
    return image;
}

} // namespace ptview
