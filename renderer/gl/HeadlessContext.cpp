#include <ptview/gl/HeadlessContext.h>

#include <glad/egl.h>
#include <glad/gl.h>

#include <cstdlib>
#include <vector>

namespace ptview {
namespace {

[[noreturn]] void fail(const std::string& what) {
    throw std::runtime_error("headless OpenGL: " + what);
}

EGLDisplay openDeviceDisplay() {
    // A first load without a display gives the client extensions and eglQueryDevicesEXT.
    if (!gladLoaderLoadEGL(EGL_NO_DISPLAY)) fail("cannot load libEGL");
    if (!GLAD_EGL_EXT_device_enumeration || !GLAD_EGL_EXT_platform_device)
        fail("EGL lacks EGL_EXT_device_enumeration / EGL_EXT_platform_device");

    EGLint deviceCount = 0;
    eglQueryDevicesEXT(0, nullptr, &deviceCount);
    if (deviceCount <= 0) fail("EGL reports no devices");
    std::vector<EGLDeviceEXT> devices(static_cast<size_t>(deviceCount));
    eglQueryDevicesEXT(deviceCount, devices.data(), &deviceCount);

    int first = 0, last = deviceCount - 1;
    if (const char* chosen = std::getenv("PTVIEW_EGL_DEVICE")) {
        first = last = std::atoi(chosen);
        if (first < 0 || first >= deviceCount)
            fail("PTVIEW_EGL_DEVICE=" + std::string(chosen) + " but there are " + std::to_string(deviceCount) + " devices");
    }
    for (int i = first; i <= last; ++i) {
        EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[static_cast<size_t>(i)], nullptr);
        EGLint major = 0, minor = 0;
        if (display != EGL_NO_DISPLAY && eglInitialize(display, &major, &minor)) return display;
    }
    fail("no EGL device could be initialized");
}

EGLContext createCoreContext(EGLDisplay display) {
    if (!eglBindAPI(EGL_OPENGL_API)) fail("EGL cannot bind the desktop OpenGL API");
    const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configCount = 0;
    eglChooseConfig(display, configAttributes, &config, 1, &configCount);
    if (configCount == 0) {
        if (!GLAD_EGL_KHR_no_config_context) fail("no EGL config supports desktop OpenGL");
        config = EGL_NO_CONFIG_KHR;
    }
    // Newest first: compute needs 4.3, the fragment path needs only 4.1.
    const EGLint versions[][2] = {{4, 6}, {4, 5}, {4, 3}, {4, 1}};
    for (const auto& version : versions) {
        const EGLint contextAttributes[] = {
            EGL_CONTEXT_MAJOR_VERSION, version[0], EGL_CONTEXT_MINOR_VERSION, version[1],
            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
        if (context != EGL_NO_CONTEXT) return context;
    }
    fail("the EGL device gives no OpenGL 4.1+ core context");
}

} // namespace

HeadlessContext::HeadlessContext() {
    EGLDisplay display = openDeviceDisplay();
    display_ = display;
    // Reload with the display so its extensions (surfaceless, no-config) are known.
    gladLoaderLoadEGL(display);
    EGLContext context = createCoreContext(display);
    context_ = context;
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
        fail("cannot make the context current without a surface (EGL_KHR_surfaceless_context)");
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress))) fail("cannot load OpenGL functions");
}

HeadlessContext::~HeadlessContext() {
    auto display = static_cast<EGLDisplay>(display_);
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display, static_cast<EGLContext>(context_));
    eglTerminate(display);
}

std::string HeadlessContext::description() const {
    return glDeviceDescription();
}

std::string glDeviceDescription() {
    return std::string(reinterpret_cast<const char*>(glGetString(GL_RENDERER))) + ", OpenGL " +
           reinterpret_cast<const char*>(glGetString(GL_VERSION));
}

} // namespace ptview
