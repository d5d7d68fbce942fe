// What the panels say where it depends on numbers and state (issue 37: "1 programs compiled", and
// "left: full, sobol" with no split view to be the left of).
#include <ptview/window/PanelText.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

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

// The sidebar's label column is as wide as "samples/frame" (Viewer.cpp), in ImGui's monospaced
// default font: a longer label beside a slider or a combo is cut ("aperture radiu", issue 37).
TEST(PanelText, EveryWidgetLabelFitsTheSidebarsLabelColumn) {
    const std::size_t column = std::string("samples/frame").size();
    const std::regex widget(R"((?:Slider\w*|Drag\w*|Combo|Input\w*|ColorEdit\d|enumCombo)\(\s*"([^"#]*)(?:##[^"]*)?")");
    int labels = 0;
    for (const auto& entry : std::filesystem::directory_iterator(PTVIEW_ASSETS_DIR "/../app/window")) {
        if (entry.path().extension() != ".cpp") continue;
        std::ifstream in(entry.path());
        std::stringstream text;
        text << in.rdbuf();
        const std::string source = text.str();
        for (std::sregex_iterator it(source.begin(), source.end(), widget), end; it != end; ++it) {
            const std::string label = (*it)[1];
            ++labels;
            EXPECT_LE(label.size(), column) << entry.path().filename() << ": \"" << label << "\" is cut in the sidebar";
        }
    }
    EXPECT_GT(labels, 30) << "the widgets were found";
}

} // namespace
} // namespace ptview
