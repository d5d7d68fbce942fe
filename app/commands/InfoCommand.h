#pragma once
#include <ptview/commands/CommandLine.h>

namespace ptview {

// `ptview info FILE`: prints the provenance a .png or .exr ptview wrote carries (Provenance.h),
// readable, and an EXR's channels. Exit code 2, naming the file, when it has none or a newer format.
int runInfoCommand(const InfoOptions& options);

} // namespace ptview
