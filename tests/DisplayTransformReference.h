#pragma once
// C++ references of the display transform of shaders/tonemap.glsl, written from the formulas
// (IEC 61966-2-1 for sRGB; the AgX description of shaders/view_transform_agx.glsl), in double,
// for tests to hold the GLSL against.

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace ptview::testing {

inline double srgbEncode(double linear) {
    const double x = std::clamp(linear, 0.0, 1.0);
    return x < 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

inline double gamma22Encode(double linear) { return std::pow(std::clamp(linear, 0.0, 1.0), 1.0 / 2.2); }

// The AgX sigmoid's polynomial fit on the log encoding [0, 1].
inline double agxContrast(double x) {
    const double x2 = x * x, x4 = x2 * x2;
    return 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x - 0.00232;
}

constexpr double kAgxMinStops = -12.47393, kAgxMaxStops = 4.026069;

// Where a linear value lands on AgX's log encoding (0: 2^-12.47, 1: 2^4.03).
inline double agxLogEncode(double linear) {
    const double stops = std::clamp(std::log2(std::max(linear, 1e-10)), kAgxMinStops, kAgxMaxStops);
    return (stops - kAgxMinStops) / (kAgxMaxStops - kAgxMinStops);
}

// Linear Rec.709 radiance to display-linear Rec.709. Rows of the inset matrix: each output
// channel keeps most of itself and takes a few percent of the other two (rows sum to 1).
inline glm::dvec3 agx(glm::dvec3 radiance) {
    const double inset[3][3] = {{0.842479062253094, 0.0784335999999992, 0.0792237451477643},
                                {0.0423282422610123, 0.878468636469772, 0.0791661274605434},
                                {0.0423756549057051, 0.0784336, 0.879142973793104}};
    const double outset[3][3] = {{1.19687900512017, -0.0980208811401368, -0.0990297440797205},
                                 {-0.0528968517574562, 1.15190312990417, -0.0989611768448433},
                                 {-0.0529716355144438, -0.0980434501171241, 1.15107367264116}};
    const glm::dvec3 in = glm::max(radiance, glm::dvec3(0.0));
    glm::dvec3 curve;
    for (int r = 0; r < 3; ++r)
        curve[r] = std::clamp(agxContrast(agxLogEncode(inset[r][0] * in.x + inset[r][1] * in.y + inset[r][2] * in.z)), 0.0, 1.0);
    glm::dvec3 out;
    for (int r = 0; r < 3; ++r)
        out[r] = std::min(std::pow(std::max(outset[r][0] * curve.x + outset[r][1] * curve.y + outset[r][2] * curve.z, 0.0), 2.2), 1.0);
    return out;
}

} // namespace ptview::testing
