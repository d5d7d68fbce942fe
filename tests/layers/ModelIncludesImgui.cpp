// Must not compile: nothing below the window knows ImGui (tests/CMakeLists.txt, Layers.*).
#include <imgui.h>
