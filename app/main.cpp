// ptview: open the viewer, render headless with `ptview render`, draw a warp with `ptview warp`,
// or time scenes with `ptview bench`.
#include "BenchCommand.h"
#include "ConvergeCommand.h"
#include "CommandLine.h"
#include "RenderCommand.h"
#include "Viewer.h"
#include "WarpCommand.h"

int main(int argc, char** argv) {
    ptview::CommandLine commandLine;
    if (auto exitCode = ptview::parseCommandLine(argc, argv, commandLine)) return *exitCode;
    if (commandLine.mode == ptview::CommandLine::Mode::Render) return ptview::runRenderCommand(commandLine.render);
    if (commandLine.mode == ptview::CommandLine::Mode::Warp) return ptview::runWarpCommand(commandLine.warp);
    if (commandLine.mode == ptview::CommandLine::Mode::Bench) return ptview::runBenchCommand(commandLine.bench);
    if (commandLine.mode == ptview::CommandLine::Mode::Converge) return ptview::runConvergeCommand(commandLine.converge);
    return ptview::runViewer(commandLine.viewer);
}
