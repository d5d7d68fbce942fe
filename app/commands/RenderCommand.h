#pragma once
#include <ptview/commands/CommandLine.h>

namespace ptview {

// `ptview render`: load, render headless through EGL, write the image. Returns the exit code.
int runRenderCommand(const RenderOptions& options);

} // namespace ptview
