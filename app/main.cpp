// ptview: open the viewer, or render headless with `ptview render`.
#include "CommandLine.h"
#include "RenderCommand.h"
#include "Viewer.h"

int main(int argc, char** argv) {
    ptview::CommandLine commandLine;
    if (auto exitCode = ptview::parseCommandLine(argc, argv, commandLine)) return *exitCode;
    if (commandLine.mode == ptview::CommandLine::Mode::Render) return ptview::runRenderCommand(commandLine.render);
    return ptview::runViewer(commandLine.viewer);
}
