#include <ptview/tracer/PixelList.h>

#include <algorithm>
#include <stdexcept>

namespace ptview {

std::vector<std::uint32_t> packedPixelsStillSampled(const std::vector<std::uint8_t>& stopped, glm::ivec2 size) {
    if (size.x <= 0 || size.y <= 0 || size.x > 0xffff || size.y > 0xffff ||
        stopped.size() != static_cast<size_t>(size.x) * static_cast<size_t>(size.y))
        throw std::invalid_argument("packedPixelsStillSampled: one flag per pixel of an image up to 65535 pixels a side expected");
    constexpr int kBlockWidth = 4, kBlockHeight = 2;
    std::vector<std::uint32_t> packed;
    for (int blockY = 0; blockY < size.y; blockY += kBlockHeight)
        for (int blockX = 0; blockX < size.x; blockX += kBlockWidth)
            for (int y = blockY; y < std::min(size.y, blockY + kBlockHeight); ++y)
                for (int x = blockX; x < std::min(size.x, blockX + kBlockWidth); ++x) {
                    const size_t row = static_cast<size_t>(size.y - 1 - y); // GL rows run bottom-up
                    if (!stopped[row * static_cast<size_t>(size.x) + static_cast<size_t>(x)])
                        packed.push_back(static_cast<std::uint32_t>(x) | (static_cast<std::uint32_t>(y) << 16));
                }
    return packed;
}

} // namespace ptview
