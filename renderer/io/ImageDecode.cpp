#include "ImageDecode.h"

#include <stb_image.h>

#include <climits>
#include <cstring>
#include <memory>
#include <string>

namespace ptview {

ImageRgba8 decodeImageRgba8(const unsigned char* bytes, std::size_t size) {
    if (size == 0) throw ImageDecodeError("empty image data");
    if (size > static_cast<std::size_t>(INT_MAX)) throw ImageDecodeError("image data above 2 GiB");
    int length = static_cast<int>(size);
    int width = 0;
    int height = 0;
    int channels = 0;
    if (!stbi_info_from_memory(bytes, length, &width, &height, &channels))
        throw ImageDecodeError(std::string("not a PNG or JPEG image stb can read (stb: ") + stbi_failure_reason() + ")");
    if (width < 1 || height < 1 || width > kMaxDecodedImageSide || height > kMaxDecodedImageSide)
        throw ImageDecodeError("image of " + std::to_string(width) + "x" + std::to_string(height) +
                               " pixels (at most " + std::to_string(kMaxDecodedImageSide) + " per side)");
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load_from_memory(bytes, length, &width, &height, &channels, 4),
                                                     stbi_image_free);
    if (!pixels) throw ImageDecodeError(std::string("cannot decode the image (stb: ") + stbi_failure_reason() + ")");
    ImageRgba8 image;
    image.width = width;
    image.height = height;
    image.rgba.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    std::memcpy(image.rgba.data(), pixels.get(), image.rgba.size());
    return image;
}

} // namespace ptview
