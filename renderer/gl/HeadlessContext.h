#pragma once
// An OpenGL core context with no window and no X server: EGL's device platform picks a GPU (or
// Mesa's software device) directly. Rendering goes to framebuffer objects.

#include <stdexcept>
#include <string>

namespace ptview {

class HeadlessContext {
public:
    // Makes the context current and loads GL. Throws std::runtime_error when no device gives a
    // core 4.1+ context. PTVIEW_EGL_DEVICE=<index> picks a device when there are several.
    HeadlessContext();
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    // "renderer, version" as the driver reports them.
    std::string description() const;

private:
    void* display_ = nullptr;
    void* context_ = nullptr;
};

// "GL_RENDERER, OpenGL GL_VERSION" of the current context (any context, a window's too).
std::string glDeviceDescription();

} // namespace ptview
