#include <ptview/tracer/WorkGroupOrder.h>

#include <cmath>
#include <numeric>

namespace ptview {

int workGroupRowStride(int rowCount) {
    if (rowCount <= 2) return 1;
    const double goldenFraction = (std::sqrt(5.0) - 1.0) / 2.0;
    const int nearest = static_cast<int>(std::lround(rowCount * goldenFraction));
    // Coprime strides lie on both sides of any value; take the closest.
    for (int offset = 0;; ++offset) {
        if (nearest - offset >= 1 && std::gcd(nearest - offset, rowCount) == 1) return nearest - offset;
        if (nearest + offset < rowCount && std::gcd(nearest + offset, rowCount) == 1) return nearest + offset;
    }
}

} // namespace ptview
