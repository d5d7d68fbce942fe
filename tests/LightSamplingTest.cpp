// Quad light sampling through the real GLSL (tests/shaders/light_probe.frag runs lights.glsl):
// the directions sampleLight produces follow the density lightPdf reports (chi-square over the
// light's surface), that density integrates to one over the light, the density a sample carries
// is the one lightPdf gives for its direction (what MIS relies on), rectangles seen from nearby at a
// usable solid angle are sampled by it (a constant density: spherical_rectangle.glsl), others by
// area (a density that varies over the light), and degenerate
// views (a point in the light's plane, on its edge, behind it, very far, a tiny light, a point
// almost touching it) give finite values only.
#include "ChiSquare.h"
#include "GlTestContext.h"
#include <ptview/gpu/GpuScene.h>
#include <ptview/gpu/GlslEnums.h>
#include <ptview/probes/ProbePass.h>
#include <ptview/gl/ShaderAssembler.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <string>

namespace ptview {
namespace {

constexpr int kSceneUnit = 2; // after the probe's two inputs
constexpr double kSignificance = 0.01; // for the whole file, Sidak-corrected per chi-square test
constexpr int kSamples = 200000;
constexpr int kBinsPerSide = 16;    // chi-square bins over the light's (s, t) parameters
constexpr int kPointsPerBinSide = 8; // midpoint rule inside each bin for its expected count

struct LightSampleOut {
    glm::vec3 wi;
    float pdf;          // what the sample carries
    float distance;
    float pdfOfSampled; // lightPdf for the sampled direction
    float radiance;
};

struct QuadLight {
    glm::vec3 center, u, v; // half-extents, as in the scene format
    glm::vec3 corner() const { return center - u - v; }
    glm::vec3 normal() const { return glm::normalize(glm::cross(u, v)); }
    float area() const { return 4.0f * glm::length(glm::cross(u, v)); }
    // The point at parameters (s, t) in [0, 1]^2.
    glm::dvec3 at(double s, double t) const {
        return glm::dvec3(corner()) + s * 2.0 * glm::dvec3(u) + t * 2.0 * glm::dvec3(v);
    }
    // The parameters of a point in the light's plane (u and v need not be orthogonal).
    glm::dvec2 parameters(glm::dvec3 p) const {
        glm::dvec3 e1 = 2.0 * glm::dvec3(u), e2 = 2.0 * glm::dvec3(v), d = p - glm::dvec3(corner());
        double a = glm::dot(e1, e1), b = glm::dot(e1, e2), c = glm::dot(e2, e2);
        double p1 = glm::dot(e1, d), p2 = glm::dot(e2, d), det = a * c - b * b;
        return {(c * p1 - b * p2) / det, (a * p2 - b * p1) / det};
    }
};

class LightProbe {
public:
    LightProbe() {
        testing::glContext();
        ShaderAssembler assembler(PTVIEW_SHADER_DIR);
        addGeneratedGlsl(assembler);
        program_ = std::make_unique<GlProgram>(assembler.assemble("fullscreen.vert"),
                                               assembler.assemble(PTVIEW_TEST_SHADER_DIR "/light_probe.frag"));
        program_->bindSamplerUnit("uInput0", 0);
        program_->bindSamplerUnit("uInput1", 1);
        gpu_.attach(*program_, kSceneUnit);
    }

    // A scene of one emitting quad: light 0.
    void setLight(const QuadLight& light) {
        Scene scene;
        Material lamp;
        lamp.name = "lamp";
        lamp.type = MaterialType::Emitter;
        lamp.radiance = glm::vec3(1.0f);
        scene.materials = {lamp};
        Shape quad;
        quad.type = ShapeType::Quad;
        quad.center = light.center;
        quad.u = light.u;
        quad.v = light.v;
        quad.material = 0;
        scene.shapes = {quad};
        gpu_.upload(scene);
        ASSERT_EQ(gpu_.lightCount(), 1);
        normal_ = light.normal();
    }

    std::vector<LightSampleOut> sample(const std::vector<glm::vec3>& points, const std::vector<glm::vec2>& us) {
        ProbeData in0, in1;
        for (std::size_t i = 0; i < points.size(); ++i) {
            in0.emplace_back(points[i], 0.0f);
            in1.emplace_back(us[i], 0.0f, 0.0f);
        }
        std::vector<ProbeData> out = run(0, in0, in1);
        std::vector<LightSampleOut> samples;
        for (std::size_t i = 0; i < points.size(); ++i)
            samples.push_back({glm::vec3(out[0][i]), out[0][i].w, out[1][i].x, out[1][i].y, out[1][i].z});
        return samples;
    }

    // lightPdf from `point` toward each target on the light.
    std::vector<float> pdf(glm::vec3 point, const std::vector<glm::dvec3>& targets) {
        ProbeData in0, in1;
        for (const glm::dvec3& target : targets) {
            glm::dvec3 d = target - glm::dvec3(point);
            double distance = glm::length(d);
            in0.emplace_back(point, 0.0f);
            in1.emplace_back(glm::vec3(d / distance), float(distance));
        }
        std::vector<ProbeData> out = run(1, in0, in1);
        std::vector<float> pdfs;
        for (std::size_t i = 0; i < targets.size(); ++i) pdfs.push_back(out[0][i].x);
        return pdfs;
    }

private:
    std::vector<ProbeData> run(int mode, const ProbeData& in0, const ProbeData& in1) {
        glUseProgram(program_->id());
        gpu_.bind();
        glUniform1i(program_->uniformLocation("uProbeMode"), mode);
        glUniform1i(program_->uniformLocation("uLight"), 0);
        glUniform3f(program_->uniformLocation("uLightNormal"), normal_.x, normal_.y, normal_.z);
        return runProbePass(*program_, int(in0.size()), {in0, in1}, 2);
    }

    std::unique_ptr<GlProgram> program_;
    GpuScene gpu_;
    glm::vec3 normal_{0.0f, 1.0f, 0.0f};
};

LightProbe& probe() {
    static LightProbe instance;
    return instance;
}

std::vector<glm::vec2> uniformSquare(int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<glm::vec2> us;
    for (int i = 0; i < count; ++i) us.push_back({unit(rng), unit(rng)});
    return us;
}

// The Cornell box's light, larger: 1 x 0.8, facing down (cross(u, v) = -y).
const QuadLight kRectangle{{0.0f, 1.0f, 0.0f}, {0.5f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.4f}};
const QuadLight kParallelogram{{0.0f, 1.0f, 0.0f}, {0.5f, 0.0f, 0.0f}, {0.2f, 0.0f, 0.4f}};

struct ViewCase {
    std::string label;
    QuadLight light;
    glm::vec3 point;
    bool bySolidAngle; // expected: sampled as a spherical rectangle (constant density)
};

void PrintTo(const ViewCase& c, std::ostream* out) { *out << c.label; }

const std::vector<ViewCase>& viewCases() {
    static const std::vector<ViewCase> cases = {
        // Within two half-diagonals (0.64 here) of the centre: by solid angle.
        {"below", kRectangle, {0.1f, 0.0f, 0.2f}, true},             // about 0.63 sr
        {"beside_and_close", kRectangle, {0.9f, 0.8f, 0.3f}, true},  // seen at a slant, 0.27 sr
        {"almost_touching", kRectangle, {0.1f, 0.95f, 0.05f}, true}, // about 5.6 sr
        // Beyond: by area.
        {"farther", kRectangle, {0.1f, -1.5f, 0.2f}, false},         // 2.5 away, 0.12 sr
        {"far", kRectangle, {3.0f, -20.0f, 0.2f}, false},            // about 2e-3 sr
        {"parallelogram", kParallelogram, {0.0f, 0.0f, 0.0f}, false},
    };
    return cases;
}

class QuadLightSampling : public ::testing::TestWithParam<ViewCase> {};

// Expected fraction of samples per (s, t) bin: lightPdf (solid angle) times cos / distance^2
// (to area), integrated over the bin by the midpoint rule.
std::vector<double> expectedFractions(const ViewCase& c) {
    const int side = kBinsPerSide * kPointsPerBinSide;
    std::vector<glm::dvec3> targets;
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) targets.push_back(c.light.at((i + 0.5) / side, (j + 0.5) / side));
    std::vector<float> pdfs = probe().pdf(c.point, targets);
    std::vector<double> fractions(kBinsPerSide * kBinsPerSide, 0.0);
    const double cellArea = double(c.light.area()) / double(side * side);
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) {
            glm::dvec3 d = targets[std::size_t(j * side + i)] - glm::dvec3(c.point);
            double distance2 = glm::dot(d, d);
            double cosLight = std::abs(glm::dot(glm::dvec3(c.light.normal()), d)) / std::sqrt(distance2);
            int bin = (j / kPointsPerBinSide) * kBinsPerSide + i / kPointsPerBinSide;
            fractions[std::size_t(bin)] += double(pdfs[std::size_t(j * side + i)]) * cosLight / distance2 * cellArea;
        }
    return fractions;
}

TEST_P(QuadLightSampling, DensityIntegratesToOneOverTheLight) {
    const ViewCase& c = GetParam();
    probe().setLight(c.light);
    double total = 0.0;
    for (double f : expectedFractions(c)) total += f;
    // The midpoint rule's error on this smooth integrand is far below 1e-3 at 128 x 128 points.
    EXPECT_NEAR(total, 1.0, 2e-3) << c.label;
}

TEST_P(QuadLightSampling, SamplesFollowTheDensityLightPdfReports) {
    const ViewCase& c = GetParam();
    probe().setLight(c.light);
    std::vector<glm::vec3> points(kSamples, c.point);
    // A seed per case: area sampling is affine in u, so cases sharing numbers would share noise.
    const auto seed = std::uint32_t(std::find_if(viewCases().begin(), viewCases().end(),
                                                 [&](const ViewCase& v) { return v.label == c.label; }) - viewCases().begin());
    std::vector<LightSampleOut> samples = probe().sample(points, uniformSquare(kSamples, 7u + seed));

    std::vector<double> observed(kBinsPerSide * kBinsPerSide, 0.0);
    int failed = 0, outside = 0;
    double worstMismatch = 0.0, minPdf = INFINITY, maxPdf = 0.0;
    for (const LightSampleOut& s : samples) {
        if (!(s.pdf > 0.0f) || !std::isfinite(s.pdf)) {
            ++failed;
            continue;
        }
        minPdf = std::min(minPdf, double(s.pdf));
        maxPdf = std::max(maxPdf, double(s.pdf));
        // MIS: the density a sample carries is the one lightPdf gives its direction.
        worstMismatch = std::max(worstMismatch, std::abs(double(s.pdfOfSampled) / double(s.pdf) - 1.0));
        glm::dvec2 st = c.light.parameters(glm::dvec3(c.point) + double(s.distance) * glm::dvec3(s.wi));
        int i = int(std::floor(st.x * kBinsPerSide)), j = int(std::floor(st.y * kBinsPerSide));
        // Float rounding can put a sample on the boundary a hair outside.
        if (st.x < -1e-4 || st.x > 1.0 + 1e-4 || st.y < -1e-4 || st.y > 1.0 + 1e-4) {
            ++outside;
            continue;
        }
        i = std::clamp(i, 0, kBinsPerSide - 1);
        j = std::clamp(j, 0, kBinsPerSide - 1);
        observed[std::size_t(j * kBinsPerSide + i)] += 1.0;
    }
    EXPECT_EQ(failed, 0);
    EXPECT_EQ(outside, 0) << "samples off the light";
    EXPECT_LT(worstMismatch, 1e-4) << "sample density vs lightPdf";
    if (c.bySolidAngle)
        EXPECT_LT(maxPdf / minPdf - 1.0, 1e-4) << "not sampled uniformly in solid angle";
    else
        EXPECT_GT(maxPdf / minPdf - 1.0, 1e-4) << "expected area sampling (a density that varies over the light)";

    std::vector<double> expected = expectedFractions(c);
    for (double& e : expected) e *= kSamples;
    testing::ChiSquareResult result = testing::chiSquareTest(observed, expected);
    const double significance = testing::sidakSignificance(kSignificance, int(viewCases().size()));
    std::printf("  %-20s %s, density %.4g..%.4g\n", c.label.c_str(), testing::describe(result).c_str(), minPdf, maxPdf);
    EXPECT_GT(result.pValue, significance) << c.label << ": " << testing::describe(result) << "\n"
                                           << testing::worstBinsTable(observed, expected);
}

INSTANTIATE_TEST_SUITE_P(Views, QuadLightSampling, ::testing::ValuesIn(viewCases()),
                         [](const ::testing::TestParamInfo<ViewCase>& info) { return info.param.label; });

// Points where the spherical-rectangle formulas divide by zero or lose every digit: in the light's
// plane (on it, on its edge and corner, beside it), a hair in front of it, behind it, very far,
// and a 0.2 mm light. Light sampling gives finite densities, unit directions and either a sample
// or nothing (density 0); lightPdf stays finite.
TEST(QuadLightSamplingDegenerate, EveryOutputIsFinite) {
    const QuadLight tiny{{0.0f, 1.0f, 0.0f}, {1e-4f, 0.0f, 0.0f}, {0.0f, 0.0f, 1e-4f}};
    struct Case {
        QuadLight light;
        glm::vec3 point;
    };
    const std::vector<Case> cases = {
        {kRectangle, {0.1f, 1.0f, 0.1f}},   {kRectangle, {0.5f, 1.0f, 0.0f}},     {kRectangle, {0.5f, 1.0f, 0.4f}},
        {kRectangle, {2.0f, 1.0f, 0.0f}},   {kRectangle, {0.0f, 1.0f - 1e-6f, 0.0f}},
        {kRectangle, {0.5f, 1.0f - 1e-6f, 0.4f}}, {kRectangle, {0.0f, 1.5f, 0.0f}}, {kRectangle, {1e5f, -1e5f, 3e4f}},
        {kRectangle, {0.7f, 0.999f, 0.0f}}, {tiny, {0.0f, 0.0f, 0.0f}},           {tiny, {1e-4f, 1.0f - 1e-7f, 0.0f}},
    };
    const int perCase = 4096;
    for (const Case& c : cases) {
        probe().setLight(c.light);
        std::vector<glm::vec2> us = uniformSquare(perCase - 4, 11u);
        for (glm::vec2 corner : {glm::vec2(0.0f), glm::vec2(1.0f), glm::vec2(0.0f, 1.0f), glm::vec2(1.0f, 0.0f)})
            us.push_back(corner * (1.0f - 1e-7f)); // the sampler's [0, 1) corners
        std::vector<LightSampleOut> samples = probe().sample(std::vector<glm::vec3>(perCase, c.point), us);
        int bad = 0, sampled = 0;
        for (const LightSampleOut& s : samples) {
            bool finite = std::isfinite(s.pdf) && s.pdf >= 0.0f && std::isfinite(s.pdfOfSampled) && std::isfinite(s.radiance) &&
                          std::isfinite(s.wi.x) && std::isfinite(s.wi.y) && std::isfinite(s.wi.z) && std::isfinite(s.distance);
            if (finite && s.pdf > 0.0f) {
                ++sampled;
                finite = std::abs(glm::length(s.wi) - 1.0f) < 1e-3f && s.distance >= 0.0f;
            }
            bad += finite ? 0 : 1;
        }
        std::vector<glm::dvec3> targets;
        for (int k = 0; k < 64; ++k) targets.push_back(c.light.at((k % 8 + 0.5) / 8.0, (k / 8 + 0.5) / 8.0));
        for (float pdf : probe().pdf(c.point, targets)) bad += std::isfinite(pdf) && pdf >= 0.0f ? 0 : 1;
        EXPECT_EQ(bad, 0) << "point (" << c.point.x << ", " << c.point.y << ", " << c.point.z << "), light half-size "
                          << c.light.u.x << ": " << sampled << " of " << perCase << " sampled";
    }
}

} // namespace
} // namespace ptview
