#pragma once
// The viewer's question before it reads a folder that a sent image's scene, or a glTF model, names
// outside its own folder (ReadScope.h): the window's answer to what `--allow-dir DIR` says on the
// command line. Asked before the scene is loaded, so it has a loop of its own.

#include <functional>
#include <string>
#include <vector>

struct GLFWwindow;

namespace ptview {

// Shows `question` (already printable) in the window with Allow and Cancel until one is chosen:
// Allow by its button or Enter, Cancel by its button, Escape or closing the window. Needs ImGui
// set up on the window. `takePressedKeys` hands over the GLFW keys pressed since it was last called,
// as the window's key callback recorded them (Viewer.cpp onKey): ImGui sees keys only as held down
// at a frame's start, and one tapped during a slow frame would be lost.
bool askToAllowFolder(GLFWwindow* window, const std::string& question,
                      const std::function<std::vector<int>()>& takePressedKeys);

} // namespace ptview
