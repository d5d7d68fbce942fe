// The sample generators of shaders/sampler.glsl, run on the GPU through the warp probe's identity
// warp: grid and stratified fill every stratum exactly once, the sequences are uniform, sobol and
// stratified integrate a smooth function with less error than random, and pixels and dimensions
// get decorrelated sequences.
#include "ChiSquare.h"
#include "GlTestContext.h"
#include <ptview/probes/WarpProbe.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace ptview {
namespace {

using testing::ChiSquareResult;

constexpr double kSignificance = 0.01; // for the whole file, Sidak-corrected per chi-square test
constexpr int kChiSquareTests = 3 /* uniformity */ + 3 /* joint uniformity of two dimensions */;

const WarpProbe& probe() {
    testing::glContext();
    static const WarpProbe instance;
    return instance;
}

struct SamplerRequest {
    SamplerMode mode = SamplerMode::Random;
    int count = 1024;
    std::uint32_t samplesPerPixel = 1024;
    std::uint32_t dimension = 0;
    std::uint32_t sampleBudget = 0; // 0: samplesPerPixel
    std::uint32_t seed = 0;
};

// What the sampler hands a path: u of sample i % samplesPerPixel in pixel i / samplesPerPixel.
std::vector<glm::vec2> samplerPoints(const SamplerRequest& sampler) {
    WarpRequest request;
    request.warp = Warp::Square;
    request.sampler = sampler.mode;
    request.count = sampler.count;
    request.samplesPerPixel = sampler.samplesPerPixel;
    request.sampleBudget = sampler.sampleBudget;
    request.seed = sampler.seed;
    request.dimension = sampler.dimension;
    std::vector<glm::vec2> points;
    for (const WarpSample& sample : probe().sample(request)) points.push_back(sample.u);
    return points;
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
    const double n = double(a.size());
    double meanA = 0.0, meanB = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        meanA += a[i] / n;
        meanB += b[i] / n;
    }
    double covariance = 0.0, varianceA = 0.0, varianceB = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        covariance += (a[i] - meanA) * (b[i] - meanB);
        varianceA += (a[i] - meanA) * (a[i] - meanA);
        varianceB += (b[i] - meanB) * (b[i] - meanB);
    }
    return covariance / std::sqrt(varianceA * varianceB);
}

// Chi-square of pairs (x, y) in [0,1)^2 against the uniform distribution on a side x side grid.
ChiSquareResult uniformityTest(const std::vector<glm::dvec2>& points, int side, const std::string& label) {
    std::vector<double> observed(std::size_t(side * side), 0.0);
    for (glm::dvec2 p : points) {
        int x = std::min(int(p.x * side), side - 1), y = std::min(int(p.y * side), side - 1);
        observed[std::size_t(y * side + x)] += 1.0;
    }
    std::vector<double> expected(observed.size(), double(points.size()) / double(observed.size()));
    ChiSquareResult result = testing::chiSquareTest(observed, expected);
    const double significance = testing::sidakSignificance(kSignificance, kChiSquareTests);
    std::printf("  %-28s %s\n", label.c_str(), testing::describe(result).c_str());
    EXPECT_GT(result.pValue, significance)
        << label << ": " << testing::describe(result) << ", significance " << significance << "\n"
        << testing::worstBinsTable(observed, expected, [&](std::size_t bin) {
               return "cell (" + std::to_string(bin % side) + ", " + std::to_string(bin / side) + ")";
           });
    return result;
}

// ---- Strata

TEST(Sampler, GridAndStratifiedPutOneSampleInEachCellOfEachPattern) {
    // A budget of 1024 is a 32 x 32 grid; 2048 samples per pixel are two whole patterns.
    const int side = 32, pattern = side * side, pixels = 4;
    for (SamplerMode mode : {SamplerMode::Grid, SamplerMode::Stratified}) {
        for (std::uint32_t dimension : {0u, 1u, 2u, 7u}) {
            SCOPED_TRACE(std::string(samplerModeName(mode)) + ", dimension " + std::to_string(dimension));
            std::vector<glm::vec2> points =
                samplerPoints({mode, 2 * pattern * pixels, 2 * pattern, dimension, std::uint32_t(pattern)});
            int misplaced = 0, identicalToFirstPattern = 0;
            for (int block = 0; block < 2 * pixels; ++block) { // pixel block / 2, pattern block % 2
                std::vector<int> hits(std::size_t(pattern), 0);
                for (int i = 0; i < pattern; ++i) {
                    glm::vec2 u = points[std::size_t(block * pattern + i)];
                    ASSERT_TRUE(u.x >= 0.0f && u.x < 1.0f && u.y >= 0.0f && u.y < 1.0f) << u.x << ", " << u.y;
                    int x = int(u.x * side), y = int(u.y * side);
                    ++hits[std::size_t(y * side + x)];
                    if (mode == SamplerMode::Grid && u != (glm::vec2(x, y) + 0.5f) / float(side)) ++misplaced;
                    if (block % 2 == 1 && u == points[std::size_t((block - 1) * pattern + i)]) ++identicalToFirstPattern;
                }
                int emptyCells = 0, crowdedCells = 0;
                for (int count : hits) {
                    emptyCells += count == 0 ? 1 : 0;
                    crowdedCells += count > 1 ? 1 : 0;
                }
                EXPECT_EQ(emptyCells, 0) << "pixel " << block / 2 << ", pattern " << block % 2;
                EXPECT_EQ(crowdedCells, 0) << "pixel " << block / 2 << ", pattern " << block % 2;
            }
            EXPECT_EQ(misplaced, 0) << "grid points off their cell centres";
            // The second pattern is a new one: stratified draws new jitter and a new cell order.
            if (mode == SamplerMode::Stratified) {
                EXPECT_LT(identicalToFirstPattern, pattern / 100);
            }
        }
    }
}

TEST(Sampler, StratifiedJitterNeverRoundsIntoTheNextCell) {
    // A large pattern (256 x 256 cells) over 4M samples: cell + jitter is a float sum, and for
    // cells 128..255 it rounds up to cell + 1 whenever jitter is within 2^-17 of 1, which put
    // about one sample in 10^5 into its neighbour's cell (and, from the last cell, at u = 1).
    const int side = 256, pattern = side * side, pixels = 16;
    int crowded = 0, outside = 0;
    for (std::uint32_t seed : {0u, 1u})
        for (std::uint32_t dimension : {0u, 1u}) {
            std::vector<glm::vec2> points = samplerPoints(
                {SamplerMode::Stratified, pattern * pixels, std::uint32_t(pattern), dimension, 0u, seed});
            for (int pixel = 0; pixel < pixels; ++pixel) {
                std::vector<bool> taken(std::size_t(pattern), false);
                for (int i = 0; i < pattern; ++i) {
                    glm::vec2 u = points[std::size_t(pixel * pattern + i)];
                    if (!(u.x < 1.0f && u.y < 1.0f)) {
                        ++outside;
                        continue;
                    }
                    std::size_t cell = std::size_t(int(u.y * side) * side + int(u.x * side)); // exact: side is 2^8
                    crowded += taken[cell] ? 1 : 0;
                    taken[cell] = true;
                }
            }
        }
    EXPECT_EQ(crowded, 0) << "samples in a cell that already had one";
    EXPECT_EQ(outside, 0) << "samples with a coordinate of 1";
}

// Owen-scrambled Sobol' points of one pixel, in aligned blocks of 2^k samples, are (0, k, 2)-nets:
// every elementary interval of area 2^-k (2^a by 2^(k-a) cells, any a) holds exactly one point. A
// wrong generator for dimension 1 (its closed form, sobolDimension1) breaks this: a wrong step of
// its sum over bit supersets that moves bit j + 2^s to bit j shows from k = 2^s + 1 on (below, the
// bits it moves are the same in the whole block, a digital shift that keeps the net), so blocks
// go up to 2^17 samples.
TEST(Sampler, SobolBlocksOfAPowerOfTwoSamplesAreNets) {
    const int maxLog2 = 17, samplesPerPixel = 1 << maxLog2, pixels = 1;
    for (std::uint32_t dimension : {0u, 1u, 6u}) {
        SCOPED_TRACE("path dimension " + std::to_string(dimension));
        std::vector<glm::vec2> points =
            samplerPoints({SamplerMode::Sobol, samplesPerPixel * pixels, std::uint32_t(samplesPerPixel), dimension, 0u, 3u});
        int crowdedIntervals = 0;
        for (int log2 = 1; log2 <= maxLog2; ++log2) {
            const int block = 1 << log2;
            for (int start = 0; start < samplesPerPixel * pixels; start += block)
                for (int a = 0; a <= log2; ++a) { // 2^a columns, 2^(log2 - a) rows
                    std::vector<int> hits(std::size_t(block), 0);
                    for (int i = start; i < start + block; ++i) {
                        glm::vec2 u = points[std::size_t(i)]; // 24-bit values: the scaling is exact
                        int column = int(u.x * float(1 << a)), row = int(u.y * float(1 << (log2 - a)));
                        crowdedIntervals += ++hits[std::size_t((row << a) + column)] > 1 ? 1 : 0;
                    }
                }
        }
        EXPECT_EQ(crowdedIntervals, 0) << "elementary intervals with a second point";
    }
}

// ---- Uniformity

TEST(Sampler, RandomStratifiedAndSobolAreUniform) {
    for (SamplerMode mode : {SamplerMode::Random, SamplerMode::Stratified, SamplerMode::Sobol}) {
        // 16 pixels of 4096: whole patterns for stratified, a power of two for sobol.
        std::vector<glm::dvec2> points;
        for (glm::vec2 u : samplerPoints({mode, 65536, 4096, 3u, 0u, 11u})) {
            ASSERT_TRUE(u.x >= 0.0f && u.x < 1.0f && u.y >= 0.0f && u.y < 1.0f) << u.x << ", " << u.y;
            points.push_back(glm::dvec2(u));
        }
        uniformityTest(points, 16, samplerModeName(mode));
    }
}

// ---- Integration error

// A smooth integrand that does not split into a product of 1D factors.
double integrand(glm::dvec2 u) { return u.x * std::exp(u.x * u.y); }
const double kIntegral = std::exp(1.0) - 2.0; // int_0^1 (e^x - 1) dx

// Root mean square error of 256-sample pixel estimates of the integral, over 256 pixels.
double pixelRmse(SamplerMode mode) {
    const int pixels = 256, samplesPerPixel = 256;
    std::vector<glm::vec2> points = samplerPoints({mode, pixels * samplesPerPixel, samplesPerPixel, 1u, 0u, 7u});
    double squaredError = 0.0;
    for (int pixel = 0; pixel < pixels; ++pixel) {
        double sum = 0.0;
        for (int i = 0; i < samplesPerPixel; ++i) sum += integrand(glm::dvec2(points[std::size_t(pixel * samplesPerPixel + i)]));
        double error = sum / samplesPerPixel - kIntegral;
        squaredError += error * error;
    }
    return std::sqrt(squaredError / pixels);
}

TEST(Sampler, SobolAndStratifiedIntegrateASmoothFunctionBetterThanRandom) {
    const double random = pixelRmse(SamplerMode::Random);
    const double stratified = pixelRmse(SamplerMode::Stratified);
    const double sobol = pixelRmse(SamplerMode::Sobol);
    std::printf("  RMSE at 256 spp: random %.3g, stratified %.3g (x%.1f), sobol %.3g (x%.1f)\n", random, stratified,
                random / stratified, sobol, random / sobol);
    // Random: sigma / sqrt(256) = 0.032 for this integrand. Jittered 16 x 16 strata (error ~ 1/N
    // in 2D) and Owen-scrambled Sobol' (~ N^-1.5) converge faster on smooth integrands; over 30
    // seeds the ratios measured 13.0-16.5 and 99-127.
    EXPECT_GT(random / stratified, 8.0);
    EXPECT_GT(random / sobol, 50.0);
}

// ---- Decorrelation

struct Decorrelation {
    double largestCorrelation = 0.0; // |r| over the coordinate pairs compared
    double identicalFraction = 0.0;  // samples equal in both
};

Decorrelation compare(const std::vector<glm::vec2>& a, const std::vector<glm::vec2>& b) {
    Decorrelation result;
    std::vector<double> coordinates[4];
    int identical = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        coordinates[0].push_back(a[i].x);
        coordinates[1].push_back(a[i].y);
        coordinates[2].push_back(b[i].x);
        coordinates[3].push_back(b[i].y);
        identical += a[i] == b[i] ? 1 : 0;
    }
    for (int i = 0; i < 2; ++i)
        for (int j = 2; j < 4; ++j)
            result.largestCorrelation = std::max(result.largestCorrelation, std::abs(correlation(coordinates[i], coordinates[j])));
    result.identicalFraction = double(identical) / double(a.size());
    return result;
}

// 16 pixels of 1024 samples; |r| of independent sequences is about 1 / sqrt(16384) = 0.008.
constexpr int kPixels = 16;
constexpr std::uint32_t kSamplesPerPixel = 1024;
constexpr double kMaxCorrelation = 0.05;

TEST(Sampler, DimensionsGetDecorrelatedSequences) {
    for (SamplerMode mode : {SamplerMode::Random, SamplerMode::Stratified, SamplerMode::Sobol}) {
        SCOPED_TRACE(samplerModeName(mode));
        const int count = kPixels * int(kSamplesPerPixel);
        std::vector<glm::vec2> first = samplerPoints({mode, count, kSamplesPerPixel, 1u, 0u, 5u});
        for (std::uint32_t other : {2u, 3u, 9u}) {
            std::vector<glm::vec2> second = samplerPoints({mode, count, kSamplesPerPixel, other, 0u, 5u});
            Decorrelation d = compare(first, second);
            EXPECT_LT(d.largestCorrelation, kMaxCorrelation) << "dimensions 1 and " << other;
            EXPECT_LT(d.identicalFraction, 0.01) << "dimensions 1 and " << other;
            if (other == 2u) {
                // Pairs (x of one dimension, x of the other) must fill the square uniformly, not
                // just be uncorrelated.
                std::vector<glm::dvec2> pairs;
                for (std::size_t i = 0; i < first.size(); ++i) pairs.push_back({first[i].x, second[i].x});
                uniformityTest(pairs, 8, std::string(samplerModeName(mode)) + " dims 1 x 2");
            }
        }
    }
}

TEST(Sampler, PixelsGetDecorrelatedSequences) {
    for (SamplerMode mode : {SamplerMode::Random, SamplerMode::Stratified, SamplerMode::Sobol}) {
        SCOPED_TRACE(samplerModeName(mode));
        std::vector<glm::vec2> points = samplerPoints({mode, kPixels * int(kSamplesPerPixel), kSamplesPerPixel, 4u, 0u, 5u});
        // Sample i of pixel p against sample i of pixel p + 1.
        std::vector<glm::vec2> left(points.begin(), points.end() - kSamplesPerPixel);
        std::vector<glm::vec2> right(points.begin() + kSamplesPerPixel, points.end());
        Decorrelation d = compare(left, right);
        EXPECT_LT(d.largestCorrelation, kMaxCorrelation);
        EXPECT_LT(d.identicalFraction, 0.01);
    }
}

} // namespace
} // namespace ptview
