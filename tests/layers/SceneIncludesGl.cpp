// Must not compile: the scene model knows no OpenGL (tests/CMakeLists.txt, Layers.*).
#include <ptview/gl/GlObjects.h>
