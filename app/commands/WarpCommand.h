#pragma once
#include <ptview/commands/CommandLine.h>

namespace ptview {

// `ptview warp`: draw a warp's points headless to a PNG. Returns the exit code.
int runWarpCommand(const WarpOptions& options);

} // namespace ptview
