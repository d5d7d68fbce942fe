// Must not compile: the GPU's records are prepared without OpenGL (tests/CMakeLists.txt, Layers.*).
#include <ptview/gl/BufferTexture.h>
