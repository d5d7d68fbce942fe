#pragma once
// Expands `#include "file.glsl"` in GLSL sources. Each file is included once per program, and
// every file's text is preceded by `#line N ID` so a driver's error can be mapped back to the
// file and line it came from (GLSL #line takes a source-string number, not a name).

#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace ptview {

class ShaderError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct AssembledShader {
    std::string source;
    std::vector<std::string> files; // source-string number -> file name, as shown to the user

    // Rewrites a driver's info log so "0:12(5)" or "0(12)" reads "shaders/bsdf.glsl:12".
    std::string annotateLog(const std::string& driverLog) const;
};

class ShaderAssembler {
public:
    // Includes are looked up in includeDir.
    explicit ShaderAssembler(std::filesystem::path includeDir);

    // entry is a path relative to includeDir, or absolute. Throws ShaderError naming the file
    // and line of a bad or missing include.
    AssembledShader assemble(const std::filesystem::path& entry) const;

    const std::filesystem::path& includeDir() const { return includeDir_; }

    // What specialization uses: `#include "include"` reads `file` from the include directory
    // instead, or the generated `text` (shown in messages as "include (generated)").
    void replaceWithFile(const std::string& include, const std::string& file);
    void replaceWithText(const std::string& include, const std::string& text);

    struct Replacement {
        bool isGenerated;
        std::string text; // a file name, or the generated source
    };

private:
    std::filesystem::path includeDir_;
    std::map<std::string, Replacement> replacements_;
};

} // namespace ptview
