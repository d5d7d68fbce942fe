// ptview: open the viewer, render headless with `ptview render`, draw a warp with `ptview warp`,
// time scenes with `ptview bench`, or record the paths behind a pixel with `ptview paths`.
#include <ptview/commands/BenchCommand.h>
#include <ptview/commands/ConvergeCommand.h>
#include <ptview/commands/CommandLine.h>
#include <ptview/io/ImageIO.h>
#include <ptview/commands/InfoCommand.h>
#include <ptview/commands/PathsCommand.h>
#include <ptview/commands/RenderCommand.h>
#include <ptview/window/Viewer.h>
#include <ptview/commands/WarpCommand.h>

#include <exception>
#include <iostream>
#include <new>

namespace {

int runCommand(int argc, char** argv) {
    ptview::CommandLine commandLine;
    if (auto exitCode = ptview::parseCommandLine(argc, argv, commandLine)) return *exitCode;
    if (commandLine.mode == ptview::CommandLine::Mode::Render) return ptview::runRenderCommand(commandLine.render);
    if (commandLine.mode == ptview::CommandLine::Mode::Warp) return ptview::runWarpCommand(commandLine.warp);
    if (commandLine.mode == ptview::CommandLine::Mode::Bench) return ptview::runBenchCommand(commandLine.bench);
    if (commandLine.mode == ptview::CommandLine::Mode::Converge) return ptview::runConvergeCommand(commandLine.converge);
    if (commandLine.mode == ptview::CommandLine::Mode::Info) return ptview::runInfoCommand(commandLine.info);
    if (commandLine.mode == ptview::CommandLine::Mode::Paths) return ptview::runPathsCommand(commandLine.paths);
    return ptview::runViewer(commandLine.viewer);
}

} // namespace

int main(int argc, char** argv) {
    ptview::reportFileSizeLimitAsWriteError();
    // The commands report what they expect; anything else still ends with its reason, never an
    // abort (std::terminate) with a core dump.
    try {
        return runCommand(argc, argv);
    } catch (const std::bad_alloc&) {
        std::cerr << "ptview: out of memory\n";
    } catch (const std::exception& e) {
        std::cerr << "ptview: " << e.what() << "\n";
    }
    return ptview::kExitRuntimeError;
}
