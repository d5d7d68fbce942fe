// Must not compile: the viewer's model is plain C++, without the GL path tracer (tests/CMakeLists.txt, Layers.*).
#include <ptview/tracer/PathTracer.h>
