// Every warp of shaders/warps.glsl, run on the GPU through the warp probe: its samples follow the
// density that sits beside it (chi-square against counts integrated from that density, never from
// the warp itself), the density integrates to one and vanishes outside the domain, the inverse
// undoes the warp, and every sample lands in the domain with a positive density.
#include "ChiSquare.h"
#include "GlTestContext.h"
#include <ptview/probes/WarpProbe.h>
#include <ptview/probes/WarpView.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

namespace ptview {
namespace {

using testing::ChiSquareResult;

constexpr double kTwoPi = 6.283185307179586;
constexpr double kSignificance = 0.01; // for the whole file, Sidak-corrected per chi-square test
constexpr int kChiSquareSamples = 400000;
constexpr int kValiditySamples = 200000;

const WarpProbe& probe() {
    testing::glContext();
    static const WarpProbe instance;
    return instance;
}

// ---- Charts and bins

// A rectangle of coordinates over (part of) a warp's domain, to bin samples and to integrate
// densities in: (x, y) on the plane for 2D domains; (z = cos theta, phi) on the sphere, where
// d omega = dz dphi, so that on both a bin's measure is its plain area in the chart.
struct Chart {
    bool spherical = false;
    double x0 = 0.0, x1 = 1.0, y0 = 0.0, y1 = 1.0;

    glm::vec3 point(double x, double y) const {
        if (!spherical) return glm::vec3(float(x), float(y), 0.0f);
        double r = std::sqrt(std::max(0.0, 1.0 - x * x));
        return glm::vec3(float(r * std::cos(y)), float(r * std::sin(y)), float(x));
    }

    glm::dvec2 coordinates(glm::vec3 p) const {
        if (!spherical) return {p.x, p.y};
        double phi = std::atan2(double(p.y), double(p.x));
        return {double(p.z), phi < 0.0 ? phi + kTwoPi : phi};
    }
};

Chart planeChart(double lo, double hi) { return {false, lo, hi, lo, hi}; }
Chart sphereChart(double zMin) { return {true, zMin, 1.0, 0.0, kTwoPi}; }

struct Binning {
    Chart chart;
    int binsX = 32;
    int binsY = 32;

    int size() const { return binsX * binsY; }

    // The bin holding p, or -1 outside the chart. Points on the far edges go to the last bin.
    int binOf(glm::vec3 p) const {
        glm::dvec2 c = chart.coordinates(p);
        double fx = (c.x - chart.x0) / (chart.x1 - chart.x0);
        double fy = (c.y - chart.y0) / (chart.y1 - chart.y0);
        if (!(fx >= 0.0 && fx <= 1.0 && fy >= 0.0 && fy <= 1.0)) return -1;
        int ix = std::min(int(fx * binsX), binsX - 1);
        int iy = std::min(int(fy * binsY), binsY - 1);
        return iy * binsX + ix;
    }

    std::string label(std::size_t bin) const {
        double w = (chart.x1 - chart.x0) / binsX, h = (chart.y1 - chart.y0) / binsY;
        double x = chart.x0 + double(bin % binsX) * w, y = chart.y0 + double(bin / binsX) * h;
        char text[96];
        std::snprintf(text, sizeof text, "%s [%.4g, %.4g) %s [%.4g, %.4g)", chart.spherical ? "z" : "x", x, x + w,
                      chart.spherical ? "phi" : "y", y, y + h);
        return text;
    }
};

// The integral of the request's density over each bin, by a midpoint rule of subX x subY points
// per bin evaluated with the GPU pdf. An even subX and an odd subY put no point on the triangle's
// edge x + y = 1 (the parities of the two sums differ), and the sphere charts put the cone's and
// the hemisphere's edges on bin edges, so only the disk's circle cuts through bins.
std::vector<double> integrateBins(const WarpRequest& request, const Binning& binning, int subX, int subY) {
    const Chart& chart = binning.chart;
    const int nx = binning.binsX * subX, ny = binning.binsY * subY;
    const double dx = (chart.x1 - chart.x0) / nx, dy = (chart.y1 - chart.y0) / ny;
    std::vector<glm::vec3> points;
    points.reserve(std::size_t(nx) * std::size_t(ny));
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) points.push_back(chart.point(chart.x0 + (i + 0.5) * dx, chart.y0 + (j + 0.5) * dy));
    std::vector<float> density = probe().pdf(request, points);

    std::vector<double> integral(std::size_t(binning.size()), 0.0);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            integral[std::size_t((j / subY) * binning.binsX + i / subX)] += density[std::size_t(j) * nx + i] * dx * dy;
    return integral;
}

// ---- The warps under test

struct WarpVariant {
    WarpInfo info;
    float cosThetaMax = 0.5f;
    std::string label; // test name suffix
    float g = 0.0f;    // henyey-greenstein's mean cosine

    bool isCone() const { return info.warp == Warp::UniformCone; }

    WarpRequest request(SamplerMode sampler, int count, std::uint32_t seed) const {
        WarpRequest request;
        request.warp = info.warp;
        request.sampler = sampler;
        request.count = count;
        request.seed = seed;
        request.cosThetaMax = cosThetaMax;
        request.g = g;
        return request;
    }

    // The domain's lower z bound on the sphere (-1: the whole sphere).
    double minZ() const {
        if (isCone()) return double(cosThetaMax);
        if (info.warp == Warp::UniformHemisphere || info.warp == Warp::CosineHemisphere) return 0.0;
        return -1.0;
    }

    // The chart that holds the whole domain.
    Chart domainChart() const {
        switch (info.domain) {
        case WarpDomain::Disk: return planeChart(-1.0, 1.0);
        case WarpDomain::Sphere: return sphereChart(-1.0);
        case WarpDomain::Square:
        case WarpDomain::Triangle: break;
        }
        return planeChart(0.0, 1.0);
    }

    // Chi-square bins: the domain chart, except that a cone zooms onto [2 cosThetaMax - 1, 1] in z
    // so that its cap fills the upper half of the bins (with an even bin count the cap's edge is a
    // bin edge) instead of one or two rows of the whole sphere.
    Binning chiSquareBinning() const {
        if (isCone()) return {sphereChart(2.0 * double(cosThetaMax) - 1.0), 32, 32};
        return {domainChart(), 32, 32};
    }

    // Whether p lies in the closed domain, up to `tolerance`.
    bool contains(glm::vec3 p, float tolerance) const {
        switch (info.domain) {
        case WarpDomain::Square:
            return p.z == 0.0f && p.x >= -tolerance && p.y >= -tolerance && p.x <= 1.0f + tolerance &&
                   p.y <= 1.0f + tolerance;
        case WarpDomain::Disk: return p.z == 0.0f && glm::length(glm::vec2(p)) <= 1.0f + tolerance;
        case WarpDomain::Triangle:
            return p.z == 0.0f && p.x >= -tolerance && p.y >= -tolerance && p.x + p.y <= 1.0f + tolerance;
        case WarpDomain::Sphere:
            return std::abs(glm::length(p) - 1.0f) <= tolerance && double(p.z) >= minZ() - tolerance;
        }
        return false;
    }

    // Whether u.y is an azimuth (phi = 2 pi u.y): its inverse may wrap from ~1 to ~0.
    bool azimuthalV() const {
        return info.warp == Warp::UniformDiskPolar || info.warp == Warp::UniformSphere || isCone() ||
               info.warp == Warp::UniformHemisphere || info.warp == Warp::HenyeyGreenstein;
    }

    // Whether the whole edge u.x = 0 lands on one point (the polar disk's centre, the pole, the
    // triangle's vertex b0 = 1), where no inverse can recover u.y.
    bool collapsesEdgeUx0() const {
        return info.warp == Warp::UniformDiskPolar || info.warp == Warp::UniformSphere || isCone() ||
               info.warp == Warp::UniformTriangle || info.warp == Warp::HenyeyGreenstein;
    }
};

void PrintTo(const WarpVariant& variant, std::ostream* out) { *out << variant.label; }

std::string testName(std::string text) {
    for (char& c : text)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return text;
}

// Every warp the product knows; the cone at a wide and a narrow opening.
std::vector<WarpVariant> warpVariants() {
    std::vector<WarpVariant> variants;
    for (const WarpInfo& info : warpInfos()) {
        if (info.warp == Warp::UniformCone) {
            variants.push_back({info, 0.5f, testName(std::string(info.name) + "-0.5")});
            variants.push_back({info, 0.95f, testName(std::string(info.name) + "-0.95")});
        } else if (info.warp == Warp::HenyeyGreenstein) {
            // backward, isotropic (the g = 0 branch), mildly and strongly forward (fog, clouds)
            for (auto [g, label] : {std::pair{-0.6f, "-m0.6"}, {0.0f, "-0"}, {0.3f, "-0.3"}, {0.9f, "-0.9"}})
                variants.push_back({info, 0.5f, testName(std::string(info.name) + label), g});
        } else {
            variants.push_back({info, 0.5f, testName(info.name)});
        }
    }
    return variants;
}

struct ChiSquareCase {
    WarpVariant variant;
    SamplerMode sampler = SamplerMode::Random;
    std::uint32_t samplesPerPixel = 0; // 0: all samples in one pixel
    std::string label;
    std::uint32_t seed = 0; // one per case: warps that are affine in u must not share their noise
};

void PrintTo(const ChiSquareCase& test, std::ostream* out) { *out << test.label; }

// Every warp under the random sampler; the cosine hemisphere, the BSDF's warp, also under the
// sequences the renderer offers (uniform in distribution too, just better spread).
const std::vector<ChiSquareCase>& chiSquareCases() {
    static const std::vector<ChiSquareCase> cases = [] {
        std::vector<ChiSquareCase> list;
        for (const WarpVariant& variant : warpVariants()) {
            list.push_back({variant, SamplerMode::Random, 0, variant.label + "_random"});
            if (variant.info.warp == Warp::CosineHemisphere)
                for (SamplerMode sampler : {SamplerMode::Stratified, SamplerMode::Sobol})
                    list.push_back({variant, sampler, 1024, variant.label + "_" + samplerModeName(sampler)});
        }
        for (std::size_t i = 0; i < list.size(); ++i) list[i].seed = 1000u + std::uint32_t(i);
        return list;
    }();
    return cases;
}

// ---- Chi-square: the samples follow the density

class WarpChiSquare : public ::testing::TestWithParam<ChiSquareCase> {};

TEST_P(WarpChiSquare, SamplesFollowTheDensity) {
    const ChiSquareCase& test = GetParam();
    WarpRequest request = test.variant.request(test.sampler, kChiSquareSamples, test.seed);
    request.samplesPerPixel = test.samplesPerPixel;
    const Binning binning = test.variant.chiSquareBinning();

    std::vector<double> observed(std::size_t(binning.size()), 0.0);
    int outside = 0;
    for (const WarpSample& sample : probe().sample(request)) {
        int bin = binning.binOf(sample.point);
        if (bin < 0)
            ++outside;
        else
            observed[std::size_t(bin)] += 1.0;
    }
    // 32 x 33 points per bin: with 8 x 9 the disk's cut bins are off enough to pull its p-values
    // measurably low over many seeds.
    std::vector<double> expected = integrateBins(request, binning, 32, 33);
    for (double& count : expected) count *= kChiSquareSamples;

    ChiSquareResult result = testing::chiSquareTest(observed, expected);
    const double significance = testing::sidakSignificance(kSignificance, int(chiSquareCases().size()));
    std::printf("  %-36s %s\n", test.label.c_str(), testing::describe(result).c_str());
    EXPECT_EQ(outside, 0) << "samples outside the binned chart";
    EXPECT_GT(result.pValue, significance)
        << test.label << ": " << testing::describe(result) << ", significance " << significance << "\n"
        << testing::worstBinsTable(observed, expected, [&](std::size_t bin) { return binning.label(bin); });
}

INSTANTIATE_TEST_SUITE_P(AllWarps, WarpChiSquare, ::testing::ValuesIn(chiSquareCases()),
                         [](const ::testing::TestParamInfo<ChiSquareCase>& info) { return info.param.label; });

// ---- Densities, inverses, domains

class Warps : public ::testing::TestWithParam<WarpVariant> {};

TEST_P(Warps, DensityIntegratesToOne) {
    const WarpVariant& variant = GetParam();
    // One bin over the whole domain, on a fine grid: 512 x 511 points on the plane (the triangle
    // needs the odd count, see integrateBins); 400 z rows on the sphere put z = 0, 0.5 and 0.95 on
    // row edges, and the midpoint rule is exact for the cosine's linear z.
    const Binning whole{variant.domainChart(), 1, 1};
    const bool spherical = whole.chart.spherical;
    // Henyey-Greenstein at g = 0.9 peaks within ~0.006 of z = 1 (its width (1 - g)^2 / 2g): many
    // thin z rows, few azimuths (it does not depend on them).
    const bool peaked = variant.info.warp == Warp::HenyeyGreenstein;
    double integral = integrateBins(variant.request(SamplerMode::Random, 1, 0), whole,
                                    peaked ? 8000 : spherical ? 400 : 512, peaked ? 4 : spherical ? 63 : 511)[0];
    EXPECT_NEAR(integral, 1.0, 1e-3);
}

TEST_P(Warps, DensityIsZeroOutsideTheDomain) {
    const WarpVariant& variant = GetParam();
    // A grid over [-2, 2]^2 (plane) or the whole sphere; points near the domain's edge are left
    // out, the rest outside must have density exactly 0.
    const Chart chart = variant.info.domain == WarpDomain::Sphere ? sphereChart(-1.0) : planeChart(-2.0, 2.0);
    std::vector<glm::vec3> points;
    for (int j = 0; j < 100; ++j)
        for (int i = 0; i < 101; ++i) {
            glm::vec3 p = chart.point(chart.x0 + (i + 0.5) * (chart.x1 - chart.x0) / 101,
                                      chart.y0 + (j + 0.5) * (chart.y1 - chart.y0) / 100);
            if (!variant.contains(p, 1e-3f)) points.push_back(p);
        }
    if (variant.info.warp == Warp::UniformSphere || variant.info.warp == Warp::HenyeyGreenstein) { // the whole sphere
        EXPECT_TRUE(points.empty());
        return;
    }
    ASSERT_FALSE(points.empty());
    std::vector<float> density = probe().pdf(variant.request(SamplerMode::Random, 1, 0), points);
    int nonzero = 0;
    for (std::size_t i = 0; i < points.size(); ++i)
        if (density[i] != 0.0f && ++nonzero <= 3)
            ADD_FAILURE() << "density " << density[i] << " at (" << points[i].x << ", " << points[i].y << ", "
                          << points[i].z << "), outside the domain";
    EXPECT_EQ(nonzero, 0) << "of " << points.size() << " points outside the domain";
}

TEST_P(Warps, InverseUndoesTheWarp) {
    const WarpVariant& variant = GetParam();
    float worst = 0.0f;
    WarpSample worstSample{};
    for (const WarpSample& sample : probe().sample(variant.request(SamplerMode::Random, kValiditySamples, 17u))) {
        glm::vec2 error = glm::abs(sample.inverse - sample.u);
        if (variant.azimuthalV()) error.y = std::min(error.y, 1.0f - error.y); // phi = 0 and 2 pi meet
        if (variant.collapsesEdgeUx0() && sample.u.x == 0.0f) error.y = 0.0f;
        if (std::max(error.x, error.y) > worst) {
            worst = std::max(error.x, error.y);
            worstSample = sample;
        }
    }
    std::printf("  %-36s largest |inverse(warp(u)) - u| = %.3g\n", variant.label.c_str(), worst);
    EXPECT_LE(worst, 1e-4f) << "at u = (" << worstSample.u.x << ", " << worstSample.u.y << "), inverse = ("
                            << worstSample.inverse.x << ", " << worstSample.inverse.y << ")";
}

TEST_P(Warps, SamplesLieInTheDomainWithPositiveDensity) {
    const WarpVariant& variant = GetParam();
    int outside = 0, zeroDensity = 0, bad = 0;
    for (const WarpSample& sample : probe().sample(variant.request(SamplerMode::Random, kValiditySamples, 5u))) {
        bool in = variant.contains(sample.point, 1e-5f) && sample.u.x >= 0.0f && sample.u.x < 1.0f &&
                  sample.u.y >= 0.0f && sample.u.y < 1.0f;
        if (variant.info.warp == Warp::Square) in = in && sample.point == glm::vec3(sample.u, 0.0f);
        bool positive = sample.pdf > 0.0f && std::isfinite(sample.pdf);
        outside += in ? 0 : 1;
        zeroDensity += positive ? 0 : 1;
        if ((!in || !positive) && ++bad <= 3)
            ADD_FAILURE() << "u = (" << sample.u.x << ", " << sample.u.y << ") -> (" << sample.point.x << ", "
                          << sample.point.y << ", " << sample.point.z << "), pdf " << sample.pdf;
    }
    EXPECT_EQ(outside, 0);
    EXPECT_EQ(zeroDensity, 0);
}

// The view's outline (the warp visualizer, `ptview warp`) encloses exactly where the warp's points
// land: a hemisphere warp is drawn on a hemisphere, not inside a whole sphere (issue 37), and every
// sample lies on or above the outline's lowest point.
TEST_P(Warps, OutlineReachesDownToWhereTheSamplesCanLandAndNoFurther) {
    const WarpVariant& variant = GetParam();
    WarpRequest request = variant.request(SamplerMode::Random, kValiditySamples, 7u);
    const float lowest = lowestCosTheta(request);
    float outlineLowestZ = 1.0f;
    for (glm::vec3 p : warpOutline(variant.info.domain, lowest))
        if (variant.info.domain != WarpDomain::Sphere || std::abs(glm::length(p) - 1.0f) < 1e-3f) // not the +z axis
            outlineLowestZ = std::min(outlineLowestZ, p.z);
    float samplesLowestZ = 1.0f;
    for (const WarpSample& sample : probe().sample(request))
        samplesLowestZ = std::min(samplesLowestZ, displayPosition(variant.info.domain, sample.point).z);
    if (variant.info.domain != WarpDomain::Sphere) {
        EXPECT_EQ(outlineLowestZ, 0.0f); // planar: outline and points in z = 0
        EXPECT_EQ(samplesLowestZ, 0.0f);
        return;
    }
    EXPECT_NEAR(outlineLowestZ, lowest, 1e-5f) << warpSupportText(request);
    EXPECT_GE(samplesLowestZ, lowest - 1e-5f) << warpSupportText(request);
    // and the samples fill the support down to its rim (within a few degrees at this many points)
    EXPECT_LT(samplesLowestZ, lowest + 0.1f) << warpSupportText(request);
}

TEST(WarpSupportText, SaysWhereEachWarpsPointsLand) {
    WarpRequest request;
    request.warp = Warp::CosineHemisphere;
    EXPECT_EQ(warpSupportText(request), "directions on the upper hemisphere (z >= 0)");
    request.warp = Warp::UniformSphere;
    EXPECT_EQ(warpSupportText(request), "directions on the whole sphere");
    request.warp = Warp::UniformCone;
    request.cosThetaMax = 0.5f;
    EXPECT_EQ(warpSupportText(request), "directions within 60 deg of +z");
    request.warp = Warp::UniformDiskConcentric;
    EXPECT_EQ(warpSupportText(request), "points in the unit disk");
}

INSTANTIATE_TEST_SUITE_P(AllWarps, Warps, ::testing::ValuesIn(warpVariants()),
                         [](const ::testing::TestParamInfo<WarpVariant>& info) { return info.param.label; });

// ---- The chi-square utility itself

TEST(ChiSquare, UpperIncompleteGammaMatchesClosedForms) {
    for (double x : {0.01, 0.5, 1.0, 3.0, 10.0, 50.0}) {
        EXPECT_NEAR(testing::regularizedGammaQ(1.0, x), std::exp(-x), 1e-12 + 1e-10 * std::exp(-x)) << x;
        EXPECT_NEAR(testing::regularizedGammaQ(0.5, x), std::erfc(std::sqrt(x)), 1e-12 + 1e-10 * std::erfc(std::sqrt(x)))
            << x;
        // Integer a: Q(k, x) = e^-x sum_{i<k} x^i / i!
        double term = std::exp(-x), sum = 0.0;
        for (int i = 0; i < 7; ++i, term *= x / i) sum += term;
        EXPECT_NEAR(testing::regularizedGammaQ(7.0, x), sum, 1e-12 + 1e-10 * sum) << x;
    }
    // Chi-square quantiles from tables: P(chi2_dof >= q) = 0.01.
    EXPECT_NEAR(testing::regularizedGammaQ(0.5 * 10, 0.5 * 23.2093), 0.01, 1e-5);
    EXPECT_NEAR(testing::regularizedGammaQ(0.5 * 100, 0.5 * 135.807), 0.01, 1e-5);
    EXPECT_NEAR(testing::regularizedGammaQ(0.5 * 1000, 0.5 * 1106.969), 0.01, 1e-5);
}

TEST(ChiSquare, PoolsSparseBinsAndRejectsImpossibleOrWrongCounts) {
    // Four sparse bins (expected 1 each) pool into one of 4, still under 5, so the pool takes in
    // the next smallest bin too: the pool and three bins remain, 3 degrees of freedom.
    std::vector<double> expected = {1, 1, 1, 1, 20, 30, 40, 50};
    std::vector<double> observed = {0, 2, 1, 1, 21, 28, 41, 50};
    ChiSquareResult fit = testing::chiSquareTest(observed, expected);
    EXPECT_EQ(fit.pooledBins, 5);
    EXPECT_EQ(fit.degreesOfFreedom, 3);
    EXPECT_GT(fit.pValue, 0.5);

    std::vector<double> skewed = {0, 0, 0, 0, 40, 30, 20, 50};
    EXPECT_LT(testing::chiSquareTest(skewed, expected).pValue, 1e-3); // chi2 = 20.7, 3 dof

    ChiSquareResult impossible = testing::chiSquareTest({1, 10, 10}, {0, 10.5, 10.5});
    EXPECT_EQ(impossible.pValue, 0.0);
    EXPECT_FALSE(impossible.impossible.empty());
}

} // namespace
} // namespace ptview
