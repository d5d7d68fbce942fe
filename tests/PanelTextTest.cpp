// What the panels say where it depends on numbers and state (issue 37: "1 programs compiled", and
// "left: full, sobol" with no split view to be the left of).
#include <ptview/window/PanelText.h>

#include <gtest/gtest.h>

namespace ptview {
namespace {

TEST(PanelText, OneOfAThingIsSingular) {
    EXPECT_EQ(countOf(1, "program"), "1 program");
    EXPECT_EQ(countOf(0, "program"), "0 programs");
    EXPECT_EQ(countOf(3, "program"), "3 programs");
}

TEST(PanelText, AViewNamesItsSideOnlyInTheSplitView) {
    EXPECT_EQ(viewHeading(false, true, Integrator::Full, SamplerMode::Sobol), "full, sobol");
    EXPECT_EQ(viewHeading(true, true, Integrator::Full, SamplerMode::Sobol), "left: full, sobol");
    EXPECT_EQ(viewHeading(true, false, Integrator::Mis, SamplerMode::Random), "right: mis, random");
}

} // namespace
} // namespace ptview
