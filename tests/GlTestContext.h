#pragma once
// One headless OpenGL context per test process, created on first use.
#include "HeadlessContext.h"

namespace ptview::testing {

inline HeadlessContext& glContext() {
    static HeadlessContext context;
    return context;
}

} // namespace ptview::testing
