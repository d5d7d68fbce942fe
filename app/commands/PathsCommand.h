#pragma once
#include <ptview/commands/CommandLine.h>

namespace ptview {

// `ptview paths`: record the paths behind a pixel on the GPU, write them as JSON and, with
// --image, a picture of them from a second camera. Returns the exit code.
int runPathsCommand(const PathsOptions& options);

} // namespace ptview
