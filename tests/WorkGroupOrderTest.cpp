#include <ptview/tracer/WorkGroupOrder.h>

#include <gtest/gtest.h>

#include <vector>

namespace ptview {
namespace {

// Image row of workgroup row y, as pathtrace.comp computes it.
int imageRow(int y, int stride, int rowCount) { return static_cast<int>((static_cast<long long>(y) * stride) % rowCount); }

TEST(WorkGroupOrder, EveryImageRowIsRenderedExactlyOnce) {
    for (int rowCount = 1; rowCount <= 2000; ++rowCount) {
        const int stride = workGroupRowStride(rowCount);
        ASSERT_GE(stride, 1) << rowCount;
        std::vector<int> timesRendered(static_cast<std::size_t>(rowCount), 0);
        for (int y = 0; y < rowCount; ++y) ++timesRendered[static_cast<std::size_t>(imageRow(y, stride, rowCount))];
        for (int row = 0; row < rowCount; ++row) ASSERT_EQ(timesRendered[static_cast<std::size_t>(row)], 1) << rowCount << " rows, row " << row;
    }
}

// llvmpipe gives each of two threads a contiguous half of the workgroups: each half must take rows
// from the top and the bottom of the image alike, or a costly bottom (a mesh on the floor) keeps
// one thread busy alone. In row order each half would take all its rows from one half.
TEST(WorkGroupOrder, EachHalfOfTheWorkGroupsTakesRowsFromBothHalvesOfTheImage) {
    for (int rowCount = 16; rowCount <= 2000; ++rowCount) {
        const int stride = workGroupRowStride(rowCount);
        for (int half = 0; half < 2; ++half) {
            const int first = half * rowCount / 2, end = (half + 1) * rowCount / 2;
            int inTopHalf = 0;
            for (int y = first; y < end; ++y) inTopHalf += imageRow(y, stride, rowCount) < rowCount / 2 ? 1 : 0;
            const double share = static_cast<double>(inTopHalf) / (end - first);
            EXPECT_GE(share, 1.0 / 3.0) << rowCount << " rows, stride " << stride << ", half " << half;
            EXPECT_LE(share, 2.0 / 3.0) << rowCount << " rows, stride " << stride << ", half " << half;
        }
    }
}

} // namespace
} // namespace ptview
