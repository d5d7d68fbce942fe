#include <ptview/gl/ShaderAssembler.h>
#include <ptview/gpu/ShaderFeatures.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <unistd.h>

namespace ptview {
namespace {

namespace fs = std::filesystem;

class ShaderAssemblerTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("ptview_assembler_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name) << text; }

    fs::path dir_;
};

size_t countOccurrences(const std::string& text, const std::string& needle) {
    size_t count = 0;
    for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++count;
    return count;
}

TEST_F(ShaderAssemblerTest, IncludesEachFileOnceWithLineDirectives) {
    write("main.frag", "#version 410 core\n#include \"a.glsl\"\n#include \"b.glsl\"\nvoid main() {}\n");
    write("a.glsl", "#include \"b.glsl\"\nfloat a() { return b(); }\n");
    write("b.glsl", "float b() { return 1.0; }\n");
    AssembledShader shader = ShaderAssembler(dir_).assemble("main.frag");

    EXPECT_EQ(shader.source.rfind("#version 410 core\n", 0), 0u) << "#version must stay first";
    EXPECT_EQ(countOccurrences(shader.source, "float b()"), 1u);
    ASSERT_EQ(shader.files.size(), 3u);
    EXPECT_EQ(shader.files[0], "main.frag");
    EXPECT_EQ(shader.files[1], "a.glsl");
    EXPECT_EQ(shader.files[2], "b.glsl");
    // b.glsl is file 2 and starts at its line 1; a.glsl resumes at its line 2 after the include.
    EXPECT_NE(shader.source.find("#line 1 2\nfloat b()"), std::string::npos);
    EXPECT_NE(shader.source.find("#line 2 1\nfloat a()"), std::string::npos);
    EXPECT_NE(shader.source.find("#line 4 0\nvoid main()"), std::string::npos);
}

TEST_F(ShaderAssemblerTest, MissingIncludeNamesFileAndLine) {
    write("main.frag", "#version 410 core\n\n#include \"nope.glsl\"\n");
    try {
        ShaderAssembler(dir_).assemble("main.frag");
        FAIL() << "expected ShaderError";
    } catch (const ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("main.frag:3: cannot find include \"nope.glsl\""), std::string::npos)
            << e.what();
    }
}

// shaders/ holds readable copies of generated includes (bsdf.glsl, light_kinds.glsl): a program
// given its own must compile that, not the copy.
TEST_F(ShaderAssemblerTest, AReplacementWinsOverTheFileOfItsName) {
    write("main.frag", "#version 410 core\n#include \"generated.glsl\"\n#include \"full.glsl\"\n");
    write("generated.glsl", "float onDisk() { return 1.0; }\n");
    write("full.glsl", "float full() { return 1.0; }\n");
    write("empty.glsl", "float empty() { return 0.0; }\n");
    ShaderAssembler assembler(dir_);
    assembler.replaceWithText("generated.glsl", "float generated() { return 2.0; }\n");
    assembler.replaceWithFile("full.glsl", "empty.glsl");
    AssembledShader shader = assembler.assemble("main.frag");
    EXPECT_NE(shader.source.find("float generated()"), std::string::npos);
    EXPECT_NE(shader.source.find("float empty()"), std::string::npos);
    EXPECT_EQ(shader.source.find("float onDisk()"), std::string::npos);
    EXPECT_EQ(shader.source.find("float full()"), std::string::npos);
}

TEST_F(ShaderAssemblerTest, MissingEntryFileIsAnError) {
    EXPECT_THROW(ShaderAssembler(dir_).assemble("absent.frag"), ShaderError);
}

TEST(AssembledShader, DriverLogsPointAtFileAndLine) {
    AssembledShader shader;
    shader.files = {"pathtrace.frag", "bsdf.glsl"};
    EXPECT_EQ(shader.annotateLog("1:12(5): error: `x' undeclared\n"), "bsdf.glsl:12:5: error: `x' undeclared\n");
    EXPECT_EQ(shader.annotateLog("0(7) : error C1008: undefined variable\n"),
              "pathtrace.frag:7 : error C1008: undefined variable\n");
    EXPECT_EQ(shader.annotateLog("unrelated text\n"), "unrelated text\n");
}

TEST(ProductShaders, EveryEntryPointTargetsGlsl410Core) {
    ShaderAssembler assembler(PTVIEW_SHADER_DIR);
    // The uber-program: every include the fragment path can pull in.
    specializeShaders(assembler, ShaderFeatures::all(), Integrator::Full, SamplerMode::Sobol);
    for (const char* entry : {"fullscreen.vert", "pathtrace.frag", "display.frag"}) {
        AssembledShader shader = assembler.assemble(entry);
        EXPECT_EQ(shader.source.rfind("#version 410 core\n", 0), 0u) << entry;
        // 4.1 has no shader storage buffers: scene data must come through textures and uniform blocks.
        static const std::regex bufferBlock(R"(\bbuffer\s+\w+\s*\{)");
        EXPECT_FALSE(std::regex_search(shader.source, bufferBlock)) << entry;
    }
    // The compute entry is the optional OpenGL 4.3 backend, over the same includes.
    EXPECT_EQ(assembler.assemble("pathtrace.comp").source.rfind("#version 430 core\n", 0), 0u);
}

} // namespace
} // namespace ptview
