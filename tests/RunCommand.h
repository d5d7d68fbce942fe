#pragma once
// Runs a shell command for end-to-end tests of the real binary.
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace ptview::testing {

struct CommandResult {
    int exitCode = -1;
    std::string output; // stdout and stderr together
};

inline CommandResult runCommand(const std::string& command) {
    CommandResult result;
    FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return result;
    char buffer[4096];
    size_t count;
    while ((count = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, count);
    int status = ::pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

inline std::string shellQuoted(const std::string& text) {
    return "'" + text + "'";
}

// xvfb-run with its auth file in the current directory (the caller cds into a scratch directory
// first). Without -f, xvfb-run makes a temporary directory of its own, and when removing it at
// exit fails it exits 5 in place of the program's exit code ("problem while cleaning up
// temporary directory": seen once under load, failing a test that expected 2).
inline std::string xvfbRun(const std::string& screen) {
    return "xvfb-run -a -f .xvfb-auth -s '-screen 0 " + screen + "' ";
}

} // namespace ptview::testing
