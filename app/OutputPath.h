#pragma once
// Checks an output file path before any work is done, so a typo costs nothing.

#include <initializer_list>
#include <optional>
#include <string>

namespace ptview {

// The path's lower-case extension when it is one of `allowed` (e.g. ".png") and its directory
// exists; otherwise prints why on stderr ("ptview: PATH: ...") and returns nullopt.
std::optional<std::string> checkOutputPath(const std::string& path, std::initializer_list<const char*> allowed);

} // namespace ptview
