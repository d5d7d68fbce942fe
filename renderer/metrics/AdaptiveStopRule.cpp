#include <ptview/metrics/AdaptiveStopRule.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ptview {

namespace {

void checkSizes(const AdaptiveStopInput& input) {
    const size_t pixels = size_t(std::max(input.width, 0)) * size_t(std::max(input.height, 0));
    if (!input.pixelRelativeMse || !input.pixelSampleCounts || !input.pixelTakesSamples ||
        input.pixelRelativeMse->size() != pixels || input.pixelSampleCounts->size() != pixels ||
        input.pixelTakesSamples->size() != pixels)
        throw std::invalid_argument("adaptive stop rule: one error, count and flag per pixel expected");
}

} // namespace

std::vector<double> neighbourhoodRelativeMse(const AdaptiveStopInput& input) {
    checkSizes(input);
    const int w = input.width, h = input.height;
    std::vector<double> means(input.pixelRelativeMse->size(), 0.0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double sum = 0.0;
            int count = 0;
            for (int v = std::max(y - 1, 0); v <= std::min(y + 1, h - 1); ++v)
                for (int u = std::max(x - 1, 0); u <= std::min(x + 1, w - 1); ++u) {
                    sum += (*input.pixelRelativeMse)[size_t(v) * size_t(w) + size_t(u)];
                    ++count;
                }
            means[size_t(y) * size_t(w) + size_t(x)] = sum / count;
        }
    return means;
}

double marginalStopThreshold(const AdaptiveStopInput& input, const std::vector<double>& relativeMse,
                             double targetRelativeMse) {
    checkSizes(input);
    const size_t pixels = relativeMse.size();
    if (pixels == 0) return 0.0;
    // With t = sqrt(mu), a pixel still sampled ends at min(c, a t): c = min(e, the bound), a =
    // sqrt(v) = sqrt(e n). The image's predicted error is piecewise linear in t with a bend at each
    // c / a, so one pass over the bends, sorted, solves it exactly (a check in the viewer runs this
    // over every pixel of the window).
    const double target = targetRelativeMse * double(pixels);
    struct Bend {
        double t, cap, rate; // t = cap / rate
        bool operator<(const Bend& other) const { return t < other.t; }
    };
    double stopped = 0.0, saturated = 0.0, slope = 0.0, all = 0.0;
    std::vector<Bend> bends;
    for (size_t i = 0; i < pixels; ++i) {
        const double e = std::max(relativeMse[i], 0.0);
        if (!(*input.pixelTakesSamples)[i]) {
            stopped += e;
            continue;
        }
        const double cap = std::min(e, input.maxThresholdRelativeMse);
        const double rate = std::sqrt(e * std::max((*input.pixelSampleCounts)[i], 1));
        if (cap <= 0.0 || rate <= 0.0) continue; // ends at 0 whatever mu
        slope += rate;
        all += cap;
        bends.push_back({cap / rate, cap, rate});
    }
    all += stopped;
    if (all <= target) return std::numeric_limits<double>::infinity();
    if (stopped >= target) return 0.0;
    std::sort(bends.begin(), bends.end());
    // Between bends, error = stopped + saturated + slope t.
    for (const Bend& bend : bends) {
        if (stopped + saturated + slope * bend.t >= target) break;
        saturated += bend.cap;
        slope -= bend.rate;
    }
    if (!(slope > 0.0)) return std::numeric_limits<double>::infinity(); // rounding at the last bend
    const double t = (target - stopped - saturated) / slope;
    return t * t;
}

std::vector<std::uint8_t> pixelsToStop(const AdaptiveStopInput& input) {
    const std::vector<double> neighbourhood = neighbourhoodRelativeMse(input);
    const int w = input.width, h = input.height;
    const size_t pixels = neighbourhood.size();
    auto index = [w](int x, int y) { return size_t(y) * size_t(w) + size_t(x); };
    std::vector<std::uint8_t> couldStop(pixels, 0);
    for (size_t i = 0; i < pixels; ++i) {
        const int samples = (*input.pixelSampleCounts)[i];
        if (!(*input.pixelTakesSamples)[i] || samples < input.minSamples) continue;
        const double threshold = std::min(input.thresholdRelativeMsePerSample * samples, input.maxThresholdRelativeMse);
        couldStop[i] = neighbourhood[i] <= threshold ? 1 : 0;
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
