// ptview: open the viewer, render headless with `ptview render`, or draw a warp with `ptview warp`.
#include "CommandLine.h"
#include "RenderCommand.h"
#include "Viewer.h"
#include "WarpCommand.h"

int main(int argc, char** argv) {
    ptview::CommandLine commandLine;
    if (auto exitCode = ptview::parseCommandLine(argc, argv, commandLine)) return *exitCode;
    if (commandLine.mode == ptview::CommandLine::Mode::Render) return ptview::runRenderCommand(commandLine.render);
    if (commandLine.mode == ptview::CommandLine::Mode::Warp) return ptview::runWarpCommand(commandLine.warp);
    return ptview::runViewer(commandLine.viewer);
}
