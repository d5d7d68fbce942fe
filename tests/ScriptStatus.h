#pragma once
// Reading the `status` lines a viewer script prints (docs/viewer-script.md): the window tests
// check what the real viewer did through them.

#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace ptview::testing {

// The `status` lines of a run's output, in order.
inline std::vector<std::string> statusLines(const std::string& output) {
    std::vector<std::string> lines;
    std::istringstream in(output);
    for (std::string line; std::getline(in, line);)
        if (line.rfind("status ", 0) == 0) lines.push_back(line);
    return lines;
}

// One `name=value` field of a status line (a quoted value keeps its quotes); "<missing NAME>"
// when the line has none, so a test's failure message says which.
inline std::string field(const std::string& statusLine, const std::string& name) {
    std::smatch match;
    std::regex pattern(" " + name + "=(\"[^\"]*\"|\\S+)");
    return std::regex_search(statusLine, match, pattern) ? match[1].str() : "<missing " + name + ">";
}

} // namespace ptview::testing
