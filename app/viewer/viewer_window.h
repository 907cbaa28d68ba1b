#pragma once
// The viewer's window: GLFW and ImGui lifetimes, and the callbacks that turn window events into
// the InputQueue (keys, buttons, cursor, wheel) and the list of dropped files.
#include "viewer/viewer_input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <memory>
#include <string>
#include <vector>

namespace shadowlab::app {

// Terminates GLFW however the viewer leaves.
struct GlfwSession {
    bool ok = glfwInit() == GLFW_TRUE;
    ~GlfwSession() {
        if (ok) glfwTerminate();
    }
};

struct WindowDeleter {
    void operator()(GLFWwindow* w) const { glfwDestroyWindow(w); }
};
using WindowPtr = std::unique_ptr<GLFWwindow, WindowDeleter>;

// An OpenGL 4.5 core window with an sRGB-capable default framebuffer; nullptr when refused.
WindowPtr createViewerWindow(int width, int height);

// What the callbacks fill between two frames.
struct WindowEvents {
    InputQueue input;
    std::vector<std::string> droppedFiles;
    bool exposed = false;  // resized or uncovered since the last frame
};
// Installs the callbacks (before ImGui's, which chain to them). `events` must outlive the window.
void installWindowCallbacks(GLFWwindow* window, WindowEvents& events);

// Uploads and mipmaps one small sRGB texture and waits for it, while the first scene is still
// parsing: llvmpipe spends ~290 ms on its first mipmapped sRGB upload (then 10-40 ms per 1024^2
// Sponza texture), which would otherwise freeze the first frame of streamed textures.
void warmUpTextureUploads();

struct ImGuiSession {
    explicit ImGuiSession(GLFWwindow* window);
    ~ImGuiSession();
    ImGuiSession(const ImGuiSession&) = delete;
    ImGuiSession& operator=(const ImGuiSession&) = delete;
};

}  // namespace shadowlab::app
