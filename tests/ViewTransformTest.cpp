// The display transform of shaders/tonemap.glsl run on the GPU through
// tests/shaders/display_transform_probe.frag, against the C++ references of
// DisplayTransformReference.h: the exact sRGB curve, gamma 2.2 for older files, and AgX.
#include "DisplayTransformReference.h"
#include "GlTestContext.h"
#include <ptview/gl/ShaderAssembler.h>
#include <ptview/gpu/GlslEnums.h>
#include <ptview/probes/ProbePass.h>
#include <ptview/settings/ToneMapper.h>

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace ptview {
namespace {

struct ProbeResult {
    glm::vec3 encoded; // what the display pass writes (before 8-bit quantization)
    glm::vec3 linear;  // the tone mapper's display-linear output
};

class DisplayTransformProbe {
public:
    DisplayTransformProbe() {
        testing::glContext();
        ShaderAssembler assembler(PTVIEW_SHADER_DIR);
        addGeneratedGlsl(assembler);
        program_ = std::make_unique<GlProgram>(assembler.assemble("fullscreen.vert"),
                                               assembler.assemble(PTVIEW_TEST_SHADER_DIR "/display_transform_probe.frag"));
        program_->bindSamplerUnit("uItems", 0);
    }

    std::vector<ProbeResult> run(const std::vector<glm::vec3>& radiances, ToneMapper toneMapper,
                                 DisplayTransfer transfer = DisplayTransfer::Srgb, float exposureScale = 1.0f) {
        ProbeData items;
        for (const glm::vec3& radiance : radiances) items.emplace_back(radiance, 0.0f);
        glUseProgram(program_->id());
        glUniform1f(program_->uniformLocation("uExposureScale"), exposureScale);
        glUniform1ui(program_->uniformLocation("uToneMapper"), static_cast<GLuint>(toneMapper));
        glUniform1ui(program_->uniformLocation("uDisplayTransfer"), static_cast<GLuint>(transfer));
        std::vector<ProbeData> out = runProbePass(*program_, int(items.size()), {items}, 2);
        std::vector<ProbeResult> results;
        for (std::size_t k = 0; k < items.size(); ++k) results.push_back({glm::vec3(out[0][k]), glm::vec3(out[1][k])});
        return results;
    }

private:
    std::unique_ptr<GlProgram> program_;
};

DisplayTransformProbe& probe() {
    static DisplayTransformProbe instance;
    return instance;
}

std::vector<glm::vec3> greys(const std::vector<float>& values) {
    std::vector<glm::vec3> result;
    for (float v : values) result.emplace_back(v);
    return result;
}

// Clamp passes display-linear values through, so the encoding alone is seen; the points straddle
// the linear segment's end (0.0031308) where gamma 2.2 and sRGB differ most.
TEST(DisplayTransfer, SrgbAndGamma22MatchTheirFormulas) {
    const std::vector<float> values = {0.0f, 0.0001f, 0.001f, 0.003f, 0.0031308f, 0.0032f, 0.01f, 0.05f, 0.18f, 0.5f, 0.9f, 1.0f, 2.0f};
    const std::vector<ProbeResult> srgb = probe().run(greys(values), ToneMapper::Clamp, DisplayTransfer::Srgb);
    const std::vector<ProbeResult> gamma = probe().run(greys(values), ToneMapper::Clamp, DisplayTransfer::Gamma22);
    for (std::size_t k = 0; k < values.size(); ++k) {
        EXPECT_NEAR(srgb[k].encoded.x, testing::srgbEncode(values[k]), 2e-6) << values[k];
        EXPECT_NEAR(gamma[k].encoded.x, testing::gamma22Encode(values[k]), 2e-6) << values[k];
    }
    // The two curves are not the same: at 0.001 sRGB's linear segment gives 0.0129, gamma 2.2 0.0433.
    EXPECT_LT(srgb[2].encoded.x, 0.5f * gamma[2].encoded.x);
}

// sRGB's two pieces meet at 0.0031308 without a step (a pure power has no join to get wrong, but an
// infinite slope at black, which is why sRGB has the linear piece).
TEST(DisplayTransfer, SrgbIsContinuousAtItsJoinAndBothEncodingsAreMonotonic) {
    const std::vector<ProbeResult> join = probe().run(greys({0.0031307f, 0.0031309f}), ToneMapper::Clamp, DisplayTransfer::Srgb);
    EXPECT_NEAR(join[0].encoded.x, 0.0404486f, 1e-5f);
    EXPECT_LT(join[1].encoded.x - join[0].encoded.x, 1e-5f);
    EXPECT_GE(join[1].encoded.x, join[0].encoded.x);
    std::vector<float> values;
    for (int i = 0; i <= 4000; ++i) values.push_back(static_cast<float>(i) / 4000.0f);
    for (DisplayTransfer transfer : {DisplayTransfer::Srgb, DisplayTransfer::Gamma22}) {
        const std::vector<ProbeResult> out = probe().run(greys(values), ToneMapper::Clamp, transfer);
        for (std::size_t k = 1; k < out.size(); ++k) EXPECT_GE(out[k].encoded.x, out[k - 1].encoded.x) << values[k];
        EXPECT_EQ(out.front().encoded.x, 0.0f);
        EXPECT_NEAR(out.back().encoded.x, 1.0f, 1e-6f);
    }
}

TEST(Agx, MapsBlackToBlackAndAnyRadianceBelowWhite) {
    const std::vector<glm::vec3> inputs = {glm::vec3(0.0f), glm::vec3(1e3f), glm::vec3(1e6f), glm::vec3(FLT_MAX),
                                           glm::vec3(1e6f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1e6f)};
    const std::vector<ProbeResult> out = probe().run(inputs, ToneMapper::Agx);
    EXPECT_EQ(out[0].linear, glm::vec3(0.0f));
    EXPECT_EQ(out[0].encoded, glm::vec3(0.0f));
    for (std::size_t k = 1; k < inputs.size(); ++k)
        for (int c = 0; c < 3; ++c) {
            EXPECT_TRUE(std::isfinite(out[k].linear[c])) << k;
            EXPECT_LT(out[k].linear[c], 1.0f) << "input " << k << " channel " << c << ": AgX's shoulder never reaches 1";
            EXPECT_GE(out[k].linear[c], 0.0f) << k;
        }
    // The inset matrix mixes a little of each primary into the others, so that a blinding red
    // runs to white instead of staying a flat clipped red...
    EXPECT_GT(out[4].linear.g, 0.9f);
    // ...while a bright one keeps its hue and takes in some of the others.
    const std::vector<ProbeResult> bright = probe().run({glm::vec3(20.0f, 0.0f, 0.0f)}, ToneMapper::Agx);
    EXPECT_GT(bright[0].linear.r, 0.9f);
    EXPECT_GT(bright[0].linear.g, 0.2f);
    EXPECT_LT(bright[0].linear.g, 0.8f * bright[0].linear.r);
}

TEST(Agx, IsFiniteForHugeTinyAndNonFiniteInput) {
    const float inf = std::numeric_limits<float>::infinity();
    const std::vector<glm::vec3> inputs = {glm::vec3(inf), glm::vec3(1e-30f), glm::vec3(-5.0f), glm::vec3(FLT_MIN),
                                           glm::vec3(inf, 0.0f, 1.0f)};
    const std::vector<ProbeResult> out = probe().run(inputs, ToneMapper::Agx);
    for (std::size_t k = 0; k < inputs.size(); ++k)
        for (int c = 0; c < 3; ++c) {
            EXPECT_TRUE(std::isfinite(out[k].encoded[c])) << k;
            EXPECT_GE(out[k].encoded[c], 0.0f) << k;
            EXPECT_LE(out[k].encoded[c], 1.0f) << k;
        }
    EXPECT_EQ(out[2].encoded, glm::vec3(0.0f)) << "negative radiance is black";
}

TEST(Agx, IsMonotonicAlongTheGreyAxis) {
    std::vector<float> values;
    for (int i = -200; i <= 100; ++i) values.push_back(0.18f * std::exp2(static_cast<float>(i) / 10.0f)); // 2^-20 .. 2^10 times grey
    const std::vector<ProbeResult> out = probe().run(greys(values), ToneMapper::Agx);
    // Past 2^6.5 times grey the encoding is clamped and the output constant, up to float rounding.
    for (std::size_t k = 1; k < out.size(); ++k) EXPECT_GE(out[k].linear.x + 1e-5f, out[k - 1].linear.x) << values[k];
    EXPECT_GT(out.back().linear.x, out.front().linear.x + 0.99f) << "the range runs from black to near white";
}

// The log encoding puts 0.18 at 10/16.5 of its range, where the sigmoid gives about 0.5 (display
// encoded); after the 2.2 power that is about 0.21 display-linear, about 0.5 again after sRGB.
TEST(Agx, MidGreyLandsAtHalfTheDisplayRange) {
    EXPECT_NEAR(testing::agxLogEncode(0.18), 10.0 / 16.5, 1e-6);
    EXPECT_NEAR(testing::agxContrast(10.0 / 16.5), 0.5, 0.01);
    const std::vector<ProbeResult> out = probe().run({glm::vec3(0.18f)}, ToneMapper::Agx);
    EXPECT_NEAR(out[0].linear.x, std::pow(0.5, 2.2), 0.01);
    EXPECT_NEAR(out[0].encoded.x, 0.5, 0.01);
    // Grey stays grey, to the rounding of the published matrices (rows sum to 1 within 2e-4).
    EXPECT_NEAR(out[0].linear.x, out[0].linear.y, 2e-4) << "grey stays grey";
    EXPECT_NEAR(out[0].linear.x, out[0].linear.z, 2e-4);
}

TEST(Agx, ShaderAgreesWithTheCppReference) {
    std::vector<glm::vec3> inputs;
    for (float v : {0.0f, 1e-5f, 0.001f, 0.02f, 0.18f, 0.5f, 1.0f, 3.0f, 10.0f, 16.0f, 100.0f}) {
        inputs.emplace_back(v);
        inputs.emplace_back(v, 0.3f * v, 0.05f * v); // a saturated orange, where the matrices matter
        inputs.emplace_back(0.1f * v, 0.2f * v, v);
    }
    const std::vector<ProbeResult> out = probe().run(inputs, ToneMapper::Agx);
    for (std::size_t k = 0; k < inputs.size(); ++k) {
        const glm::dvec3 expected = testing::agx(glm::dvec3(inputs[k]));
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(out[k].linear[c], expected[c], 2e-4) << "input " << k << " channel " << c;
            EXPECT_NEAR(out[k].encoded[c], testing::srgbEncode(expected[c]), 5e-4) << "input " << k << " channel " << c;
        }
    }
}

// Exposure scales the radiance before the tone mapper: +1 stop of 0.09 is 0.18.
TEST(Agx, ExposureComesFirst) {
    const std::vector<ProbeResult> exposed = probe().run({glm::vec3(0.09f)}, ToneMapper::Agx, DisplayTransfer::Srgb, 2.0f);
    const std::vector<ProbeResult> direct = probe().run({glm::vec3(0.18f)}, ToneMapper::Agx);
    EXPECT_NEAR(exposed[0].encoded.x, direct[0].encoded.x, 1e-6);
}

} // namespace
} // namespace ptview
