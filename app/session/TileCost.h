#pragma once
// How long a tile of path tracing takes, learned from the tiles already rendered, so the viewer
// can fill each displayed frame with as much work as its time budget allows and no more.

#include <algorithm>
#include <cmath>

namespace ptview {

class TileCost {
public:
    // Rows worth rendering next with `seconds` of the frame's budget left, at least one (a frame
    // always makes progress) and at most rowsLeft. Before any measurement, a small probe tile.
    int rowsFitting(double seconds, int rowsLeft) const {
        int rows = secondsPerRow_ > 0.0 ? static_cast<int>(std::floor(seconds / secondsPerRow_)) : kProbeRows;
        return std::clamp(rows, 1, std::max(1, rowsLeft));
    }

    // Whether even one row would overrun `seconds`.
    bool rowOverruns(double seconds) const { return secondsPerRow_ > seconds; }

    void record(int rows, double seconds) {
        double perRow = seconds / std::max(1, rows);
        // Smoothed, but quick to follow a change of integrator, size or view.
        secondsPerRow_ = secondsPerRow_ > 0.0 ? 0.7 * secondsPerRow_ + 0.3 * perRow : perRow;
    }

    void forget() { secondsPerRow_ = 0.0; }

private:
    static constexpr int kProbeRows = 8;
    double secondsPerRow_ = 0.0;
};

} // namespace ptview
