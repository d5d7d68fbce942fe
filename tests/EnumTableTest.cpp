// The enum tables: names round-trip, and the GLSL side gets its constants from them only.
#include "Backend.h"
#include "DebugView.h"
#include "GlslEnums.h"
#include "GpuScene.h"
#include "Integrator.h"
#include "SamplerMode.h"
#include "Scene.h"
#include "Texture.h"
#include "ToneMapper.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace ptview {
namespace {

template <typename E>
void expectConsistent(const EnumTable<E>& table) {
    std::set<std::string> names;
    std::set<std::uint32_t> values;
    for (const EnumEntry<E>& entry : table) {
        EXPECT_TRUE(names.insert(entry.name).second) << "duplicate name " << entry.name;
        EXPECT_TRUE(values.insert(static_cast<std::uint32_t>(entry.value)).second) << "duplicate value of " << entry.name;
        EXPECT_EQ(table.parse(entry.name), entry.value) << entry.name;
        EXPECT_STREQ(table.name(entry.value), entry.name);
        EXPECT_EQ(&table.entry(entry.value), &entry);
    }
    EXPECT_EQ(table.names().size(), table.size());
    EXPECT_FALSE(table.parse("no such name").has_value());
}

TEST(EnumTables, NamesAndValuesAreUniqueAndRoundTrip) {
    expectConsistent(integratorNames());
    expectConsistent(samplerModeNames());
    expectConsistent(debugViewNames());
    expectConsistent(toneMapperNames());
    expectConsistent(alphaModeNames());
    expectConsistent(textureWrapNames());
    expectConsistent(backendNames());
    expectConsistent(lightKindNames());
}

// Command lines, scripts and scene files name these values: the words must not change.
TEST(EnumTables, NamesAreTheOnesUsersType) {
    using Names = std::vector<std::string>;
    EXPECT_EQ(integratorNames().names(), (Names{"naive", "direct", "mis", "full"}));
    EXPECT_EQ(samplerModeNames().names(), (Names{"random", "grid", "stratified", "sobol"}));
    EXPECT_EQ(debugViewNames().names(), (Names{"radiance", "normals", "albedo", "depth"}));
    EXPECT_EQ(toneMapperNames().names(), (Names{"reinhard", "aces", "clamp"}));
    EXPECT_EQ(backendNames().names(), (Names{"fragment", "compute"}));
    EXPECT_EQ(alphaModeNames().names(), (Names{"opaque", "mask", "blend"})); // glTF's, in lower case
    EXPECT_EQ(textureWrapNames().names(), (Names{"repeat", "clamp", "mirror"}));
    EXPECT_EQ(textureWrapNames().nameList(), "repeat, clamp, mirror"); // the loader's message lists them so
}

std::string shaderSources() {
    std::string text;
    for (const auto& file : std::filesystem::directory_iterator(PTVIEW_SHADER_DIR)) {
        std::ifstream in(file.path());
        std::ostringstream content;
        content << in.rdbuf();
        text += content.str();
    }
    return text;
}

// The numbers the GPU records hold (GpuScene.cpp, GpuTextures.cpp cast the enums) are the ones
// surface_alpha.glsl and textures.glsl compare with.
TEST(GlslEnums, AlphaAndWrapModesAreNumberedAsTheGpuRecordsHoldThem) {
    const std::string generated = glslEnumConstants();
    for (const char* constant : {"const uint kAlphaModeOpaque = 0u;", "const uint kAlphaModeMask = 1u;",
                                 "const uint kAlphaModeBlend = 2u;", "const uint kTextureWrapRepeat = 0u;",
                                 "const uint kTextureWrapClampToEdge = 1u;", "const uint kTextureWrapMirroredRepeat = 2u;"})
        EXPECT_NE(generated.find(constant), std::string::npos) << constant;
}

// No shader defines a generated constant itself: a hand-written copy could disagree with the
// table. (A misspelt name fails to compile in the render tests, which run every integrator,
// sampler, view and tone mapper.)
TEST(GlslEnums, ShadersDefineNoneOfTheGeneratedConstants) {
    const std::string shaders = shaderSources();
    const std::string generated = glslEnumConstants();
    static const std::regex definition(R"(const uint (k\w+) = (\d+)u;)");
    int constants = 0;
    for (std::sregex_iterator it(generated.begin(), generated.end(), definition), end; it != end; ++it) {
        const std::string name = (*it)[1];
        ++constants;
        // int as well: the alpha modes and wrap modes were hand-written ints before their tables.
        EXPECT_FALSE(std::regex_search(shaders, std::regex("const\\s+u?int\\s+" + name + "\\b")))
            << name << " is defined by hand in a shader";
    }
    // integrators, samplers, views, tone mappers, light kinds, materials, light paths, alpha modes, wrap modes
    EXPECT_EQ(constants, 4 + 4 + 4 + 3 + 8 + 9 + 6 + 3 + 3);
}

} // namespace
} // namespace ptview
