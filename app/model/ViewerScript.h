#pragma once
// `ptview --script FILE`: a list of viewer commands, one a line, parsed and validated in full
// before any window opens. A script that loads has no syntax left to fail on, so the viewer that
// executes it only meets run-time failures (a missing material, an unreadable file).
// The format and every command: docs/viewer-script.md, or viewerScriptReference().

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace ptview {

// One validated command. The words are kept as written (so a message can quote them) and
// converted on demand: after validation the accessors below cannot fail on a word that the
// command's table entry says is a number. Asking for the wrong type is a programming error
// (std::logic_error).
struct ScriptCommand {
    int line = 0;       // 1-based line in the script file
    std::string verb;
    // The arguments as written. A command whose last argument is a path gets the rest of the
    // line, trimmed, as that one word (paths may hold spaces). For set-material and set-light:
    // the values after NAME.FIELD.
    std::vector<std::string> words;
    // set-material / set-light: NAME.FIELD split at the last dot (material names may hold dots).
    // Whether NAME exists is the executor's check: the scene may change while the script runs.
    std::string target, field;

    float number(std::size_t i) const;                 // finite float
    int integer(std::size_t i) const;
    std::uint32_t unsignedInteger(std::size_t i) const; // seed
    glm::vec3 vec3(std::size_t first) const;           // words[first .. first + 2]
    // words[i] is the keyword written in place of a value ("auto", "none", "on").
    bool isWord(std::size_t i, const char* keyword) const;
};

struct ViewerScript {
    std::filesystem::path path;
    std::vector<ScriptCommand> commands;
};

// The message is "FILE:LINE: verb: reason", or "FILE: cannot read ..." when the file is missing.
class ScriptError : public std::runtime_error {
public:
    using runtime_error::runtime_error;
};

// Throws ScriptError at the first bad line.
ViewerScript loadViewerScript(const std::filesystem::path& path);
// sourceName is only for messages and ViewerScript::path.
ViewerScript parseViewerScript(const std::string& text, const std::filesystem::path& sourceName);

// Every command with its arguments, their ranges and its meaning, one line a command (the fields
// of set-material and set-light indented below it): for --help and the docs. Generated from the
// table the parser validates with, so the two cannot disagree.
const char* viewerScriptReference();

// The verbs of that table, in its order: the executor (ScriptRunner) has a handler for each.
std::vector<std::string> viewerScriptVerbs();

} // namespace ptview
