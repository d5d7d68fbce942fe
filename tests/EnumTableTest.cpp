// The enum tables: names round-trip, and the GLSL side gets its constants from them only.
#include <ptview/settings/Backend.h>
#include <ptview/settings/DebugView.h>
#include <ptview/settings/DenoiseAlgorithm.h>
#include "GeneratedGlsl.h"
#include <ptview/gpu/GlslEnums.h>
#include <ptview/gpu/GpuScene.h>
#include <ptview/settings/Integrator.h>
#include <ptview/settings/SamplerMode.h>
#include <ptview/scene/Scene.h>
#include <ptview/scene/Texture.h>
#include <ptview/settings/ToneMapper.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
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
    expectConsistent(displayTransferNames());
    expectConsistent(alphaModeNames());
    expectConsistent(textureWrapNames());
    expectConsistent(backendNames());
    expectConsistent(lightKindNames());
    expectConsistent(denoiseAlgorithmNames());
}

// Command lines, scripts and scene files name these values: the words must not change.
TEST(EnumTables, NamesAreTheOnesUsersType) {
    using Names = std::vector<std::string>;
    EXPECT_EQ(integratorNames().names(), (Names{"naive", "direct", "mis", "full"}));
    EXPECT_EQ(samplerModeNames().names(), (Names{"random", "grid", "stratified", "sobol"}));
    EXPECT_EQ(debugViewNames().names(), (Names{"radiance", "normals", "albedo", "depth"}));
    EXPECT_EQ(toneMapperNames().names(), (Names{"reinhard", "aces", "clamp", "agx", "ocio"}));
    EXPECT_EQ(displayTransferNames().names(), (Names{"srgb", "gamma-2.2"})); // "gamma-2.2" is read from older files too
    EXPECT_EQ(backendNames().names(), (Names{"fragment", "compute"}));
    EXPECT_EQ(alphaModeNames().names(), (Names{"opaque", "mask", "blend"})); // glTF's, in lower case
    EXPECT_EQ(textureWrapNames().names(), (Names{"repeat", "clamp", "mirror"}));
    EXPECT_EQ(denoiseAlgorithmNames().names(), (Names{"atrous", "regression"})); // provenance: absent is the first
    EXPECT_EQ(textureWrapNames().nameList(), "repeat, clamp, mirror"); // the loader's message lists them so
}

// Every shader file but the checked-in copies of generated includes: name -> text.
std::map<std::string, std::string> handWrittenShaders() {
    std::set<std::string> generated;
    for (const testing::GeneratedInclude& include : testing::generatedIncludes()) generated.insert(include.name);
    std::map<std::string, std::string> shaders;
    for (const auto& file : std::filesystem::directory_iterator(PTVIEW_SHADER_DIR)) {
        const std::string name = file.path().filename().string();
        if (generated.count(name)) continue;
        std::ifstream in(file.path());
        std::ostringstream content;
        content << in.rdbuf();
        shaders[name] = content.str();
    }
    return shaders;
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

// No shader defines a generated constant or the frame block itself: a hand-written copy could
// disagree with the C++. (A misspelt name fails to compile in the render tests, which run every
// integrator, sampler, view and tone mapper.)
TEST(GlslEnums, ShadersDefineNoneOfTheGeneratedConstants) {
    const std::map<std::string, std::string> shaders = handWrittenShaders();
    static const std::regex definition(R"(const\s+\w+\s+(k\w+)\s*=)");
    int constants = 0;
    for (const testing::GeneratedInclude& include : testing::generatedIncludes()) {
        for (std::sregex_iterator it(include.text.begin(), include.text.end(), definition), end; it != end; ++it) {
            const std::string name = (*it)[1];
            ++constants;
            const std::regex byHand("const\\s+\\w+\\s+" + name + "\\b");
            for (const auto& [file, text] : shaders)
                EXPECT_FALSE(std::regex_search(text, byHand))
                    << file << " defines " << name << ", which " << include.name << " has (generated from C++)";
        }
    }
    for (const auto& [file, text] : shaders)
        EXPECT_FALSE(std::regex_search(text, std::regex(R"(uniform\s+FrameBlock\b)")))
            << file << " declares FrameBlock, which frame_uniforms.glsl has (generated from C++)";
    const std::string enums = glslEnumConstants();
    static const std::regex enumDefinition(R"(const uint k\w+ = \d+u;)");
    EXPECT_EQ(std::distance(std::sregex_iterator(enums.begin(), enums.end(), enumDefinition), std::sregex_iterator()),
              4 + 4 + 4 + 5 + 2 + 8 + 10 + 6 + 3 + 3 + 2); // integrators, samplers, views, tone mappers,
                                                      // display transfers, light kinds, materials, light
                                                      // paths, alpha modes, wrap modes; edge-ray counts
    EXPECT_GT(constants, 60); // and the layouts' numbers
}

} // namespace
} // namespace ptview
