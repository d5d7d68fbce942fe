#pragma once
// The build's git commit (`git describe --always --dirty`), generated at build time.

namespace ptview {

const char* ptviewVersion();

} // namespace ptview
