#pragma once
// `ptview converge`: what accuracy costs in time. Renders a scene progressively with each
// configuration (integrator / sampler / MAX_DEPTH [/clamp=VALUE] [/denoise]), measures at 1, 2, 4, ... spp the GPU time and
// the error against a reference, and writes convergence.csv, convergence.png (error against time,
// log-log) and summary.md (time to reach an error, efficiency, bias) into the output directory.
// docs/accuracy.md shows what it found.
#include <ptview/commands/CommandLine.h>

#include <optional>
#include <string>
#include <vector>

namespace ptview {

// "naive/random/8,mis/sobol/8": nullopt and `error` for anything else.
std::optional<std::vector<ConvergeConfig>> parseConvergeConfigs(const std::string& text, std::string& error);

int runConvergeCommand(const ConvergeOptions& options);

} // namespace ptview
