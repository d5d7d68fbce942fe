#pragma once
#include <ptview/commands/CommandLine.h>

namespace ptview {

// The interactive viewer: a GLFW window showing the converging image, with an ImGui panel.
// Returns the exit code.
int runViewer(const ViewerOptions& options);

} // namespace ptview
