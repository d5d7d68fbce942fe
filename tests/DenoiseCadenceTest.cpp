// How often the viewer denoises while it accumulates (app/session/DenoiseCadence.h): every frame
// when a denoise is cheap, at most kTimeShare of the time when it is dear, at once when nothing
// accumulates.
#include <ptview/session/DenoiseCadence.h>

#include <gtest/gtest.h>

namespace ptview {
namespace {

TEST(DenoiseCadence, TheFirstDenoiseIsDueAtOnce) {
    DenoiseCadence cadence;
    EXPECT_TRUE(cadence.due(0.0, true));
    EXPECT_EQ(cadence.expectedSeconds(), 0.0);
}

TEST(DenoiseCadence, ACheapDenoiseRunsEveryFrame) {
    DenoiseCadence cadence;
    cadence.record(0.005); // 5 ms: a quarter of a 33 ms frame is more
    EXPECT_TRUE(cadence.due(0.033, true));
}

TEST(DenoiseCadence, ADearDenoiseTakesAtMostItsShareOfTheTime) {
    DenoiseCadence cadence;
    cadence.record(0.1); // 100 ms: due 400 ms after the last one began
    EXPECT_FALSE(cadence.due(0.033, true));
    EXPECT_FALSE(cadence.due(0.39, true));
    EXPECT_TRUE(cadence.due(0.1 / DenoiseCadence::kTimeShare, true));
}

TEST(DenoiseCadence, WithoutAccumulationTheLastSamplesAreDenoisedAtOnce) {
    DenoiseCadence cadence;
    cadence.record(1.0);
    EXPECT_TRUE(cadence.due(0.0, false));
}

TEST(DenoiseCadence, TheCostFollowsAChangeQuickly) {
    DenoiseCadence cadence;
    cadence.record(0.2);
    for (int i = 0; i < 10; ++i) cadence.record(0.01);
    EXPECT_LT(cadence.expectedSeconds(), 0.02);
    cadence.forget();
    EXPECT_EQ(cadence.expectedSeconds(), 0.0);
}

} // namespace
} // namespace ptview
