#include "gl/headless_context.h"

#include "gl/gl.h"
#include "gl/sanitizer_support.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <vector>

namespace shadowlab {
namespace {

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const std::size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)); p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

// Makes a GL 4.5 core (debug) context current without a surface; EGL_NO_CONTEXT on failure.
EGLContext makeCoreContext(EGLDisplay display) {
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) return EGL_NO_CONTEXT;
    if (!eglBindAPI(EGL_OPENGL_API)) return EGL_NO_CONTEXT;
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(display, configAttribs, &config, 1, &count) || count < 1) config = nullptr;
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE, EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttribs);
    if (context == EGL_NO_CONTEXT) return EGL_NO_CONTEXT;
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        eglDestroyContext(display, context);
        return EGL_NO_CONTEXT;
    }
    return context;
}

}  // namespace

std::unique_ptr<HeadlessContext> HeadlessContext::create(std::string& error) {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) {
        error = "EGL has no eglGetPlatformDisplayEXT: cannot make a headless context";
        return nullptr;
    }

    struct Candidate {
        EGLenum platform;
        void* nativeDisplay;
        std::string name;
    };
    std::vector<Candidate> candidates;
    // Hardware devices first (NVIDIA exposes its GPUs here); Mesa's software device is skipped in
    // favour of the surfaceless platform, which is what Mesa documents for headless llvmpipe.
    if (hasExtension(clientExtensions, "EGL_EXT_device_enumeration") &&
        hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
        auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
        auto queryDeviceString =
            reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
        EGLDeviceEXT devices[16];
        EGLint deviceCount = 0;
        if (queryDevices && queryDevices(16, devices, &deviceCount)) {
            for (EGLint i = 0; i < deviceCount; ++i) {
                const char* deviceExtensions = queryDeviceString ? queryDeviceString(devices[i], EGL_EXTENSIONS) : "";
                if (hasExtension(deviceExtensions, "EGL_MESA_device_software")) continue;
                candidates.push_back({EGL_PLATFORM_DEVICE_EXT, devices[i], "EGL device " + std::to_string(i)});
            }
        }
    }
    if (hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless"))
        candidates.push_back({EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, "EGL surfaceless (Mesa)"});

    for (const Candidate& c : candidates) {
        EGLDisplay display = getPlatformDisplay(c.platform, c.nativeDisplay, nullptr);
        if (display == EGL_NO_DISPLAY) continue;
        EGLContext context = makeCoreContext(display);
        if (context == EGL_NO_CONTEXT) {
            eglTerminate(display);
            continue;
        }
        gl::keepLoadedLibrariesMappedForLeakReports();
        std::unique_ptr<HeadlessContext> result(new HeadlessContext());
        result->display_ = display;
        result->context_ = context;
        const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        result->description_ = c.name + ", " + (renderer ? renderer : "unknown renderer");
        return result;
    }
    error = "no EGL platform gave an OpenGL 4.5 core context (tried " + std::to_string(candidates.size()) +
            " candidates; is Mesa's libegl-mesa0 installed?)";
    return nullptr;
}

HeadlessContext::~HeadlessContext() {
    if (display_) {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (context_) eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }
}

}  // namespace shadowlab
