#include <ptview/metrics/AdaptiveStopRule.h>

#include <algorithm>
#include <stdexcept>

namespace ptview {

std::vector<std::uint8_t> pixelsToStop(const AdaptiveStopInput& input) {
    const int w = input.width, h = input.height;
    const size_t pixels = size_t(std::max(w, 0)) * size_t(std::max(h, 0));
    if (!input.pixelRelativeMse || !input.pixelSampleCounts || !input.pixelTakesSamples ||
        input.pixelRelativeMse->size() != pixels || input.pixelSampleCounts->size() != pixels ||
        input.pixelTakesSamples->size() != pixels)
        throw std::invalid_argument("pixelsToStop: one error, count and flag per pixel expected");
    auto index = [w](int x, int y) { return size_t(y) * size_t(w) + size_t(x); };
    std::vector<std::uint8_t> couldStop(pixels, 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = index(x, y);
            if (!(*input.pixelTakesSamples)[i] || (*input.pixelSampleCounts)[i] < input.minSamples) continue;
            double sum = 0.0;
            int count = 0;
            for (int v = std::max(y - 1, 0); v <= std::min(y + 1, h - 1); ++v)
                for (int u = std::max(x - 1, 0); u <= std::min(x + 1, w - 1); ++u) {
                    sum += (*input.pixelRelativeMse)[index(u, v)];
                    ++count;
                }
            couldStop[i] = sum <= input.thresholdRelativeMse * count ? 1 : 0;
        }
    std::vector<std::uint8_t> stop(pixels, 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (!couldStop[index(x, y)]) continue;
            bool neighboursToo = true;
            for (int v = std::max(y - 1, 0); v <= std::min(y + 1, h - 1) && neighboursToo; ++v)
                for (int u = std::max(x - 1, 0); u <= std::min(x + 1, w - 1); ++u)
                    if ((*input.pixelTakesSamples)[index(u, v)] && !couldStop[index(u, v)]) {
                        neighboursToo = false;
                        break;
                    }
            stop[index(x, y)] = neighboursToo ? 1 : 0;
        }
    const int side = std::max(input.tileSide, 1);
    if (side == 1) return stop;
    // A tile stops only as a whole: any pixel of it still sampled that does not stop keeps all.
    for (int tileY = 0; tileY * side < h; ++tileY)
        for (int tileX = 0; tileX * side < w; ++tileX) {
            const int x0 = tileX * side, x1 = std::min(x0 + side, w);
            const int yUp0 = tileY * side, yUp1 = std::min(yUp0 + side, h); // rows from the bottom
            bool whole = true;
            for (int yUp = yUp0; yUp < yUp1 && whole; ++yUp)
                for (int x = x0; x < x1; ++x) {
                    const size_t i = index(x, h - 1 - yUp);
                    if ((*input.pixelTakesSamples)[i] && !stop[i]) {
                        whole = false;
                        break;
                    }
                }
            if (whole) continue;
            for (int yUp = yUp0; yUp < yUp1; ++yUp)
                for (int x = x0; x < x1; ++x) stop[index(x, h - 1 - yUp)] = 0;
        }
    return stop;
}

} // namespace ptview
