// The error and difference views through the real display pass (shaders/display.frag,
// display_view.glsl, colormap.glsl), read back headless: each pixel's colour is the colour map
// (ColorMap.h, the legend's) at the value the C++ definitions give for that pixel, and the pixel
// zoom shows each render pixel as a block.
#include "GlTestContext.h"

#include <ptview/gl/Readback.h>
#include <ptview/metrics/ErrorMetrics.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/settings/ColorMap.h>
#include <ptview/tracer/AdaptiveSampler.h>
#include <ptview/tracer/PathTracer.h>
#include <ptview/window/ErrorLegend.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <set>
#include <tuple>

namespace ptview {
namespace {

const char* const kCornell = PTVIEW_ASSETS_DIR "/scenes/cornell.json";
constexpr glm::ivec2 kSize{32, 24}; // not square: a swapped x and y would show

glm::ivec3 bytesOf(glm::vec3 colour) {
    return glm::ivec3(glm::round(glm::clamp(colour, 0.0f, 1.0f) * 255.0f));
}

glm::ivec3 shownAt(const ImageRgba8& image, int x, int y) {
    size_t i = (static_cast<size_t>(y) * image.width + x) * 4;
    return glm::ivec3(image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]);
}

int largestChannelDifference(glm::ivec3 a, glm::ivec3 b) {
    glm::ivec3 d = glm::abs(a - b);
    return std::max(d.x, std::max(d.y, d.z));
}

// ErrorMetrics.h's per-pixel relative squared error, mean over RGB: the term compareToReference averages.
double relativeSquaredError(glm::vec3 value, glm::vec3 reference) {
    double sum = 0.0;
    for (int c = 0; c < 3; ++c) {
        double d = double(value[c]) - double(reference[c]);
        sum += d * d / (double(reference[c]) * reference[c] + kRelativeMseEpsilon);
    }
    return sum / 3.0;
}

glm::vec3 errorMapColour(double relativeError, const ErrorMapRange& range) {
    double level = std::log10(std::max(relativeError, 1e-30));
    return evaluateColorMap(kViridisPoints, static_cast<float>((level - range.errorLog10Min) / (range.errorLog10Max - range.errorLog10Min)));
}

class DisplayViews : public ::testing::Test {
protected:
    void SetUp() override {
        testing::glContext();
        tracer_ = std::make_unique<PathTracer>();
        tracer_->setScene(loadScene(kCornell));
        tracer_->setImageSize(kSize);
        tracer_->setSettings(testing::naiveSettings(3, 11));
        for (int i = 0; i < 32; ++i) tracer_->renderSample();
        statistics_ = tracer_->readStatistics();
    }

    // A reference with errors spread over the map: the mean scaled by up to +-40% and offset.
    ImageRgbF spreadReference() const {
        ImageRgbF reference(kSize.x, kSize.y);
        for (int y = 0; y < kSize.y; ++y)
            for (int x = 0; x < kSize.x; ++x) {
                float scale = 1.0f + 0.4f * std::sin(0.7f * x + 1.3f * y);
                reference.set(x, y, statistics_.mean.at(x, y) * scale + glm::vec3(0.002f * (x % 5)));
            }
        return reference;
    }

    std::unique_ptr<PathTracer> tracer_;
    PixelStatistics statistics_;
};

// The error map against a known reference: every pixel is viridis at log10 of that pixel's
// relative error, sqrt(mean over RGB of (x - ref)^2 / (ref^2 + 0.01)), placed on the legend's
// range; the mean of its squares over the image is the true error's relative MSE, so map and
// number agree. Two ranges, so the legend's scale is what moves the colours.
TEST_F(DisplayViews, ErrorMapPixelIsTheColourMapAtThePixelsRelativeError) {
    auto reference = std::make_shared<const ImageRgbF>(spreadReference());
    tracer_->setOtherImage(reference);
    double sumSquares = 0.0;
    for (int y = 0; y < kSize.y; ++y)
        for (int x = 0; x < kSize.x; ++x) sumSquares += relativeSquaredError(statistics_.mean.at(x, y), reference->at(x, y));
    EXPECT_NEAR(sumSquares / (kSize.x * kSize.y), compareToReference(statistics_.mean, *reference).relativeMse, 1e-9)
        << "the map's per-pixel quantity is the true error's per-pixel term";

    for (ErrorMapRange range : {ErrorMapRange{-3.0f, 0.0f, 1.0f}, ErrorMapRange{-1.5f, -0.5f, 1.0f}}) {
        SCOPED_TRACE(::testing::Message() << "range 10^" << range.errorLog10Min << " .. 10^" << range.errorLog10Max);
        DisplaySettings display;
        display.view = DisplayView::Error;
        display.mapRange = range;
        ImageRgba8 shown = tracer_->readToneMapped(display);
        std::set<std::tuple<int, int, int>> distinct;
        int mismatches = 0;
        for (int y = 0; y < kSize.y; ++y)
            for (int x = 0; x < kSize.x; ++x) {
                double error = std::sqrt(relativeSquaredError(statistics_.mean.at(x, y), reference->at(x, y)));
                glm::ivec3 expected = bytesOf(errorMapColour(error, range));
                distinct.insert({expected.x, expected.y, expected.z});
                if (largestChannelDifference(shownAt(shown, x, y), expected) > 1) {
                    ++mismatches;
                    ADD_FAILURE() << "pixel " << x << " " << y << " error " << error;
                    if (mismatches > 5) return;
                }
            }
        EXPECT_GT(distinct.size(), 30u) << "errors spread over the map, so a wrong scale would show";
    }
}

// Without a reference: the relative standard error of the pixel's mean from its own sums, over
// its own brightness (mean^2 - Var, never below 0, + 0.01), as readStatistics gives them.
TEST_F(DisplayViews, EstimatedErrorPixelIsTheColourMapAtTheRelativeStandardErrorOfItsMean) {
    DisplaySettings display;
    display.view = DisplayView::EstimatedError;
    display.mapRange = ErrorMapRange{-2.0f, 1.0f, 1.0f}; // 1% to 1000%: a naive render of 32 spp is noisy
    ImageRgba8 shown = tracer_->readToneMapped(display);
    std::set<std::tuple<int, int, int>> distinct;
    for (int y = 0; y < kSize.y; ++y)
        for (int x = 0; x < kSize.x; ++x) {
            glm::vec3 mean = statistics_.mean.at(x, y), variance = statistics_.varianceOfMean.at(x, y);
            double sum = 0.0;
            for (int c = 0; c < 3; ++c)
                sum += variance[c] / (std::max(double(mean[c]) * mean[c] - variance[c], 0.0) + kRelativeMseEpsilon);
            glm::ivec3 expected = bytesOf(errorMapColour(std::sqrt(sum / 3.0), display.mapRange));
            distinct.insert({expected.x, expected.y, expected.z});
            ASSERT_LE(largestChannelDifference(shownAt(shown, x, y), expected), 2) << "pixel " << x << " " << y;
        }
    EXPECT_GT(distinct.size(), 20u);
}

// render - other, the mean of RGB, onto blue .. white .. red over -range .. +range: red where
// the render is brighter, blue where darker.
TEST_F(DisplayViews, DifferenceIsTheSignedRenderMinusTheOtherImage) {
    const float grey = 0.3f;
    auto other = std::make_shared<ImageRgbF>(kSize.x, kSize.y);
    for (int y = 0; y < kSize.y; ++y)
        for (int x = 0; x < kSize.x; ++x) other->set(x, y, glm::vec3(grey));
    tracer_->setOtherImage(other);
    DisplaySettings display;
    display.view = DisplayView::Difference;
    display.mapRange.differenceRange = 0.25f;
    ImageRgba8 shown = tracer_->readToneMapped(display);
    int redder = 0, bluer = 0;
    for (int y = 0; y < kSize.y; ++y)
        for (int x = 0; x < kSize.x; ++x) {
            glm::vec3 mean = statistics_.mean.at(x, y);
            float difference = (mean.r + mean.g + mean.b) / 3.0f - grey;
            glm::ivec3 expected = bytesOf(evaluateColorMap(kBlueWhiteRedPoints, 0.5f + 0.5f * difference / 0.25f));
            glm::ivec3 colour = shownAt(shown, x, y);
            ASSERT_LE(largestChannelDifference(colour, expected), 1) << "pixel " << x << " " << y;
            if (difference > 0.05f) {
                EXPECT_GT(colour.r, colour.b) << "brighter than the other image: red, pixel " << x << " " << y;
                ++redder;
            } else if (difference < -0.05f) {
                EXPECT_LT(colour.r, colour.b) << "darker: blue, pixel " << x << " " << y;
                ++bluer;
            }
        }
    EXPECT_GT(redder, 10);
    EXPECT_GT(bluer, 10);
}

// The other image shown is displayed as the render is (A/B flipping shows no change where they
// agree), and the absolute difference of an image from itself is black.
TEST_F(DisplayViews, OtherImageIsDisplayedLikeTheRenderAndItsAbsoluteDifferenceFromItselfIsBlack) {
    tracer_->setOtherImage(std::make_shared<const ImageRgbF>(statistics_.mean));
    DisplaySettings display;
    display.exposureStops = 0.5f;
    ImageRgba8 image = tracer_->readToneMapped(display);
    display.view = DisplayView::OtherImage;
    ImageRgba8 other = tracer_->readToneMapped(display);
    display.view = DisplayView::AbsDifference;
    ImageRgba8 difference = tracer_->readToneMapped(display);
    for (int y = 0; y < kSize.y; ++y)
        for (int x = 0; x < kSize.x; ++x) {
            ASSERT_LE(largestChannelDifference(shownAt(other, x, y), shownAt(image, x, y)), 1) << x << " " << y;
            ASSERT_LE(largestChannelDifference(shownAt(difference, x, y), glm::ivec3(0)), 1) << x << " " << y;
        }
}

// A view whose image is missing or of another size shows the image, not black or garbage.
TEST_F(DisplayViews, AViewWithoutAnImageOfTheRendersSizeShowsTheImage) {
    DisplaySettings display;
    ImageRgba8 image = tracer_->readToneMapped(display);
    display.view = DisplayView::Error;
    EXPECT_EQ(tracer_->readToneMapped(display).rgba, image.rgba) << "no reference";
    tracer_->setOtherImage(std::make_shared<const ImageRgbF>(kSize.x + 1, kSize.y));
    EXPECT_EQ(tracer_->readToneMapped(display).rgba, image.rgba) << "a reference of another size";
}

// The samples-per-pixel view under adaptive sampling: pixels stopped at 64 and at 96 samples in
// stripes (Accumulator::stopPixels, as AdaptiveSampler stops them), the rest going on to 160;
// every pixel is viridis at log2 of its own count on SampleCountMapRange (64 .. 160), and the
// denoised image, which has no counts, does not replace it.
TEST_F(DisplayViews, SamplesPerPixelIsTheColourMapAtEachPixelsOwnSampleCount) {
    PathTracer tracer;
    tracer.setScene(loadScene(kCornell));
    tracer.setImageSize(kSize);
    tracer.setSettings(testing::naiveSettings(2, 5));
    const size_t pixels = static_cast<size_t>(kSize.x) * kSize.y;
    auto stopEvery = [&](int column) {
        std::vector<std::uint8_t> stop(pixels, 0);
        for (int y = 0; y < kSize.y; ++y)
            for (int x = column; x < kSize.x; x += 3) stop[static_cast<size_t>(y) * kSize.x + x] = 1;
        tracer.stopPixels(stop);
    };
    tracer.renderSamples(64);
    stopEvery(0);
    tracer.renderSamples(32);
    stopEvery(1);
    tracer.renderSamples(64);
    PixelStatistics statistics = tracer.readStatistics();
    ASSERT_EQ(tracer.sampleCount(), 160);
    const SampleCountMapRange range = sampleCountMapRange(160, kAdaptiveMinSamples);
    EXPECT_FLOAT_EQ(range.log2Min, 6.0f);
    DisplaySettings display;
    display.view = DisplayView::SamplesPerPixel;
    std::set<int> counts;
    for (bool denoised : {false, true}) {
        SCOPED_TRACE(denoised ? "denoise on" : "raw");
        display.denoised = denoised;
        if (denoised) tracer.setDenoise(DenoiseSettings{true});
        if (denoised) tracer.updateDenoised();
        ImageRgba8 shown = tracer.readToneMapped(display);
        for (int y = 0; y < kSize.y; ++y)
            for (int x = 0; x < kSize.x; ++x) {
                const int count = statistics.pixelSampleCounts[static_cast<size_t>(y) * kSize.x + x];
                ASSERT_EQ(count, x % 3 == 0 ? 64 : x % 3 == 1 ? 96 : 160) << "pixel " << x << " " << y;
                counts.insert(count);
                const float t = (std::log2(float(count)) - range.log2Min) / (range.log2Max - range.log2Min);
                ASSERT_LE(largestChannelDifference(shownAt(shown, x, y), bytesOf(evaluateColorMap(kViridisPoints, t))), 1)
                    << "pixel " << x << " " << y << " count " << count;
            }
    }
    EXPECT_EQ(counts.size(), 3u);

    // The legend: its ends are the map's ends, 64 and 160, and 128 stands where 128's colour is.
    std::vector<LegendTick> ticks = legendTicks(display, 160);
    ASSERT_EQ(ticks.size(), 3u);
    EXPECT_EQ(ticks[0].label, "64");
    EXPECT_EQ(ticks[1].label, "128");
    EXPECT_NEAR(ticks[1].position, 1.0f / (std::log2(160.0f) - 6.0f), 1e-5f);
    EXPECT_EQ(ticks[2].label, "160");
}

// The pixel zoom: drawn at 4 screen pixels per render pixel, every 4x4 block is one render
// pixel's displayed colour, the same for the error map.
TEST_F(DisplayViews, ZoomedDisplayShowsEachRenderPixelAsABlockOfItsColour) {
    tracer_->setOtherImage(std::make_shared<const ImageRgbF>(spreadReference()));
    for (DisplayView view : {DisplayView::Image, DisplayView::Error}) {
        SCOPED_TRACE(displayViewName(view));
        DisplaySettings display;
        display.view = view;
        ImageRgba8 whole = tracer_->readToneMapped(display);
        // 4:1 into a target of 40x24 screen pixels, 10x6 render pixels: render pixels 3..12 from
        // the left and 2..7 from the top, the bottom one row 16 from the bottom in GL's count.
        const glm::ivec2 target(40, 24);
        const PixelRect image{glm::ivec2(-3 * 4, -16 * 4), kSize * 4};
        ImageRgba8 zoomed = renderOffscreenRgba8(target, [&](glm::ivec2 size) {
            tracer_->display(image, display, PixelRect{{0, 0}, size});
        });
        for (int y = 0; y < target.y; ++y)     // rows top first
            for (int x = 0; x < target.x; ++x) {
                glm::ivec2 renderPixel(3 + x / 4, 7 - (target.y - 1 - y) / 4);
                ASSERT_EQ(shownAt(zoomed, x, y), shownAt(whole, renderPixel.x, renderPixel.y))
                    << "screen " << x << " " << y << " render " << renderPixel.x << " " << renderPixel.y;
            }
    }
}

// The legend reads what the map shows: a tick at each power of ten of the range, placed where
// that error's colour is; the difference's at -R, 0, +R.
TEST(ErrorLegend, TicksStandWhereTheMapHasTheirValue) {
    DisplaySettings display;
    display.view = DisplayView::Error;
    std::vector<LegendTick> ticks = legendTicks(display);
    ASSERT_EQ(ticks.size(), 4u);
    const char* labels[] = {"0.1%", "1%", "10%", "100%"};
    for (size_t i = 0; i < ticks.size(); ++i) {
        EXPECT_EQ(ticks[i].label, labels[i]);
        EXPECT_NEAR(ticks[i].position, static_cast<float>(i) / 3.0f, 1e-6f);
        double error = std::pow(10.0, -3.0 + static_cast<double>(i));
        EXPECT_EQ(bytesOf(evaluateColorMap(kViridisPoints, ticks[i].position)), bytesOf(errorMapColour(error, display.mapRange)));
    }
    display.mapRange.errorLog10Min = std::log10(0.005f), display.mapRange.errorLog10Max = std::log10(0.2f);
    ticks = legendTicks(display);
    ASSERT_EQ(ticks.size(), 4u) << "the ends, and 1% and 10% between them";
    EXPECT_EQ(ticks.front().label, "0.5%");
    EXPECT_EQ(ticks[1].label, "1%");
    EXPECT_NEAR(ticks[1].position, (-2.0f - std::log10(0.005f)) / (std::log10(0.2f) - std::log10(0.005f)), 1e-5f);
    EXPECT_EQ(ticks.back().label, "20%");
    display.view = DisplayView::Difference;
    display.mapRange.differenceRange = 0.25f;
    ticks = legendTicks(display);
    ASSERT_EQ(ticks.size(), 3u);
    EXPECT_EQ(ticks[0].label, "-0.25");
    EXPECT_EQ(ticks[1].label, "0");
    EXPECT_EQ(ticks[2].label, "+0.25");
    display.view = DisplayView::Image;
    EXPECT_TRUE(legendTicks(display).empty());
}

} // namespace
} // namespace ptview
