#include <ptview/gl/ShaderAssembler.h>

#include <ptview/io/InputFile.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

namespace ptview {
namespace {

// GLSL sources are a few KiB each; the limit only keeps a device or a stray huge file out.
constexpr std::uintmax_t kMaxShaderFileBytes = 4 * kMiB;

std::string readText(const std::filesystem::path& path, const std::string& displayName) {
    try {
        return readInputFile(path, kMaxShaderFileBytes, "shader file");
    } catch (const InputFileError& e) {
        // The display name (the include's name) is what the user can find in the shader folder.
        const std::string message = e.what();
        throw ShaderError(displayName + message.substr(path.string().size()));
    }
}

struct Expander {
    const std::filesystem::path& includeDir;
    const std::map<std::string, ShaderAssembler::Replacement>& replacements;
    AssembledShader& out;
    std::set<std::string> included;

    void expand(const std::filesystem::path& path, const std::string& displayName) {
        std::filesystem::path canonical = std::filesystem::weakly_canonical(path);
        if (included.count(canonical.string())) return;
        expandText(readText(path, displayName), displayName, canonical.string());
    }

    // An include's name may stand for another file or for generated text (ShaderAssembler::
    // replaceWithFile and replaceWithText).
    void expandInclude(const std::string& name, const std::string& from, int lineNumber) {
        auto replacement = replacements.find(name);
        if (replacement != replacements.end() && replacement->second.isGenerated) {
            expandText(replacement->second.text, name + " (generated)", "generated:" + name);
            return;
        }
        std::string file = replacement != replacements.end() ? replacement->second.text : name;
        std::filesystem::path target = includeDir / file;
        if (!std::filesystem::is_regular_file(target))
            throw ShaderError(from + ":" + std::to_string(lineNumber) + ": cannot find include \"" + file + "\"");
        expand(target, file);
    }

    void expandText(const std::string& text, const std::string& displayName, const std::string& key) {
        if (!included.insert(key).second) return;
        int fileId = static_cast<int>(out.files.size());
        out.files.push_back(displayName);
        static const std::regex includeLine(R"re(^\s*#\s*include\s*"([^"]+)"\s*$)re");
        static const std::regex versionLine(R"(^\s*#\s*version\b.*$)");

        std::istringstream lines(text);
        std::string line;
        int lineNumber = 0;
        bool needsLineDirective = true;
        while (std::getline(lines, line)) {
            ++lineNumber;
            if (!line.empty() && line.back() == '\r') line.pop_back();
            std::smatch match;
            if (std::regex_match(line, versionLine)) {
                // #version must stay the first line of the program.
                if (fileId != 0 || !out.source.empty())
                    throw ShaderError(displayName + ":" + std::to_string(lineNumber) +
                                      ": #version allowed only on the first line of the entry file");
                out.source += line + "\n";
                needsLineDirective = true;
                continue;
            }
            if (std::regex_match(line, match, includeLine)) {
                expandInclude(match[1].str(), displayName, lineNumber);
                needsLineDirective = true;
                continue;
            }
            if (needsLineDirective) {
                out.source += "#line " + std::to_string(lineNumber) + " " + std::to_string(fileId) + "\n";
                needsLineDirective = false;
            }
            out.source += line + "\n";
        }
    }
};

} // namespace

ShaderAssembler::ShaderAssembler(std::filesystem::path includeDir) : includeDir_(std::move(includeDir)) {}

void ShaderAssembler::replaceWithFile(const std::string& include, const std::string& file) {
    replacements_[include] = Replacement{false, file};
}

void ShaderAssembler::replaceWithText(const std::string& include, const std::string& text) {
    replacements_[include] = Replacement{true, text};
}

AssembledShader ShaderAssembler::assemble(const std::filesystem::path& entry) const {
    AssembledShader shader;
    Expander expander{includeDir_, replacements_, shader, {}};
    std::filesystem::path path = entry.is_absolute() ? entry : includeDir_ / entry;
    expander.expand(path, entry.is_absolute() ? entry.string() : entry.generic_string());
    return shader;
}

std::string AssembledShader::annotateLog(const std::string& driverLog) const {
    // Mesa: "0:12(5): error: ..."; NVIDIA: "0(12) : error ...".
    static const std::regex mesa(R"((\d+):(\d+)\((\d+)\))");
    static const std::regex nvidia(R"((\d+)\((\d+)\))");
    auto name = [this](const std::string& id) {
        size_t index = std::stoul(id);
        return index < files.size() ? files[index] : "source " + id;
    };
    std::istringstream lines(driverLog);
    std::string line, result;
    while (std::getline(lines, line)) {
        std::smatch match;
        if (std::regex_search(line, match, mesa) && match.position(0) == 0) {
            line = name(match[1]) + ":" + match[2].str() + ":" + match[3].str() + match.suffix().str();
        } else if (std::regex_search(line, match, nvidia) && match.position(0) == 0) {
            line = name(match[1]) + ":" + match[2].str() + match.suffix().str();
        }
        result += line + "\n";
    }
    return result;
}

} // namespace ptview
