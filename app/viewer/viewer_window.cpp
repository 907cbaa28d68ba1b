#include "viewer/viewer_window.h"

#include "gl/gl_objects.h"

#include <cstdint>
#include <vector>

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

namespace shadowlab::app {

namespace {

WindowEvents& eventsOf(GLFWwindow* window) { return *static_cast<WindowEvents*>(glfwGetWindowUserPointer(window)); }

void onKey(GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
    InputEvent e;
    e.kind = InputKind::Key;
    e.code = key;
    e.action = action;
    e.mods = mods;
    eventsOf(window).input.push(e);
}

void onMouseButton(GLFWwindow* window, int button, int action, int mods) {
    InputEvent e;
    e.kind = InputKind::MouseButton;
    e.code = button;
    e.action = action;
    e.mods = mods;
    eventsOf(window).input.push(e);
}

void onCursor(GLFWwindow* window, double x, double y) {
    InputEvent e;
    e.kind = InputKind::CursorMove;
    e.position = {x, y};
    eventsOf(window).input.push(e);
}

void onScroll(GLFWwindow* window, double /*dx*/, double dy) {
    InputEvent e;
    e.kind = InputKind::Scroll;
    e.scroll = dy;
    eventsOf(window).input.push(e);
}

void onDrop(GLFWwindow* window, int count, const char** paths) {
    for (int i = 0; i < count; ++i) eventsOf(window).droppedFiles.emplace_back(paths[i]);
}

// Resized or uncovered: the idle viewer must draw again.
void onRefresh(GLFWwindow* window) { eventsOf(window).exposed = true; }
void onFramebufferSize(GLFWwindow* window, int, int) { eventsOf(window).exposed = true; }

}  // namespace

WindowPtr createViewerWindow(int width, int height) {
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
    glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_TRUE);
    return WindowPtr(glfwCreateWindow(width, height, "shadowlab", nullptr, nullptr));
}

void installWindowCallbacks(GLFWwindow* window, WindowEvents& events) {
    glfwSetWindowUserPointer(window, &events);
    glfwSetKeyCallback(window, onKey);
    glfwSetMouseButtonCallback(window, onMouseButton);
    glfwSetCursorPosCallback(window, onCursor);
    glfwSetScrollCallback(window, onScroll);
    glfwSetDropCallback(window, onDrop);
    glfwSetWindowRefreshCallback(window, onRefresh);
    glfwSetFramebufferSizeCallback(window, onFramebufferSize);
}

ImGuiSession::ImGuiSession(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // the view state is saved as JSON instead
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window, true);  // chains to the callbacks installed before
    ImGui_ImplOpenGL3_Init("#version 450");
}

ImGuiSession::~ImGuiSession() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void warmUpTextureUploads() {
    constexpr int kSide = 64;
    const std::vector<std::uint8_t> pixels(std::size_t(kSide) * kSide * 4, 128);
    gl::Texture texture = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(texture.id(), 7, GL_SRGB8_ALPHA8, kSide, kSide);
    glTextureSubImage2D(texture.id(), 0, 0, 0, kSide, kSide, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    glGenerateTextureMipmap(texture.id());
    glFinish();
}

}  // namespace shadowlab::app
