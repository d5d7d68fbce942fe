#pragma once
// How the headless commands (render, bench, converge, warp) end on an error they did not handle
// themselves: one place that says which exceptions mean bad input (exit 2) and which a failure
// at run time (exit 1), and prints the reason the same way for all.

namespace ptview {

// Call inside a catch block: prints "ptview: REASON" for the exception being handled and returns
// kExitBadInput for std::invalid_argument (a file or option that cannot be used), else
// kExitRuntimeError.
int reportCommandError();

} // namespace ptview
