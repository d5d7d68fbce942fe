#pragma once
#include <ptview/commands/CommandLine.h>

namespace ptview {

// `ptview bench`: for each scene, the time to read it (mesh files included), to build its BVHs,
// their GPU memory, and the path-tracing rate; one Markdown table on stdout
// (docs/performance.md shows it and says how to read it). Returns the exit code.
int runBenchCommand(const BenchOptions& options);

} // namespace ptview
