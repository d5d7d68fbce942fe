// The GLSL generated from C++: the copies in shaders/ that readers open are what the generators
// write now, and the driver places every field of FrameBlock where C++ writes it.
#include "GeneratedGlsl.h"
#include <ptview/gl/GlProgram.h>
#include "GlTestContext.h"
#include <ptview/gpudata/GpuLayout.h>
#include <ptview/tracer/RecordedPath.h>

#include <glad/gl.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <unistd.h>

namespace ptview {
namespace {

std::string fileText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// A stale copy fails with the command that renews it: the expected text is written beside the
// test (ctest runs it in the build tree) for the developer to copy over.
TEST(GeneratedGlsl, CheckedInCopiesAreWhatTheGeneratorsWriteNow) {
    const std::filesystem::path shaders = PTVIEW_SHADER_DIR;
    for (const testing::GeneratedInclude& include : testing::generatedIncludes()) {
        if (fileText(shaders / include.name) == include.text) continue;
        const std::filesystem::path fresh = std::filesystem::absolute("generated-glsl") / include.name;
        std::filesystem::create_directories(fresh.parent_path());
        std::ofstream(fresh, std::ios::binary) << include.text;
        ADD_FAILURE() << "shaders/" << include.name << " is not what the C++ generates now; renew it with\n  cp "
                      << fresh.string() << " " << (shaders / include.name).string();
    }
}

TEST(GeneratedGlsl, VertexFlagsAreDistinctBits) {
    std::set<std::string> names;
    unsigned all = 0;
    for (const VertexFlagName& flag : kVertexFlagNames) {
        EXPECT_TRUE(names.insert(flag.name).second) << flag.name;
        EXPECT_EQ(flag.flag & (flag.flag - 1), 0u) << flag.name << " is not one bit";
        EXPECT_EQ(all & flag.flag, 0u) << flag.name << " shares its bit";
        all |= flag.flag;
    }
    EXPECT_EQ(all, (1u << names.size()) - 1) << "the bits are 1, 2, 4, ... with no gap";
}

// std140 is a rule the static_asserts of GpuLayout.h apply by hand; the driver is the judge.
TEST(FrameBlock, TheDriverPlacesEveryFieldWhereCppWritesIt) {
    testing::glContext();
    std::string use = "0.0";
    for (const UniformField& field : kFrameBlockFields)
        use += std::string(" + float(") + field.name + (field.glslType == "vec3" || field.glslType == "ivec2" ? ".x)" : ")");
    const std::filesystem::path entry =
        std::filesystem::temp_directory_path() / ("ptview_frame_block_" + std::to_string(::getpid()) + ".frag");
    std::ofstream(entry) << "#version 410 core\n#include \"frame_uniforms.glsl\"\nout vec4 color;\n"
                            "void main() { color = vec4(" << use << "); }\n";
    ShaderAssembler assembler(PTVIEW_SHADER_DIR);
    addGeneratedGlsl(assembler);
    GlProgram program(assembler.assemble("fullscreen.vert"), assembler.assemble(entry));
    std::filesystem::remove(entry);

    const GLuint block = glGetUniformBlockIndex(program.id(), "FrameBlock");
    ASSERT_NE(block, GL_INVALID_INDEX);
    GLint size = 0;
    glGetActiveUniformBlockiv(program.id(), block, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
    EXPECT_EQ(size, static_cast<GLint>(sizeof(FrameUniforms)));
    GLint fields = 0;
    glGetActiveUniformBlockiv(program.id(), block, GL_UNIFORM_BLOCK_ACTIVE_UNIFORMS, &fields);
    EXPECT_EQ(fields, static_cast<GLint>(std::size(kFrameBlockFields)));
    for (const UniformField& field : kFrameBlockFields) {
        GLuint index = GL_INVALID_INDEX;
        glGetUniformIndices(program.id(), 1, &field.name, &index);
        ASSERT_NE(index, GL_INVALID_INDEX) << field.name;
        GLint offset = -1;
        glGetActiveUniformsiv(program.id(), 1, &index, GL_UNIFORM_OFFSET, &offset);
        EXPECT_EQ(offset, static_cast<GLint>(field.offset)) << field.name;
    }
}

} // namespace
} // namespace ptview
