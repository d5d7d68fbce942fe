#pragma once
// The viewer's question before it reads a folder that a sent image's scene, or a glTF model, names
// outside its own folder (ReadScope.h): the window's answer to what `--allow-dir DIR` says on the
// command line. Asked before the scene is loaded, so it has a loop of its own.

#include <string>

struct GLFWwindow;

namespace ptview {

// Shows `question` (already printable) in the window with Allow and Cancel until one is chosen:
// Allow by its button or Enter, Cancel by its button, Escape or closing the window. Needs ImGui
// set up on the window.
bool askToAllowFolder(GLFWwindow* window, const std::string& question);

} // namespace ptview
