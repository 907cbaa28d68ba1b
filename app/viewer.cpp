// The interactive viewer: `shadowlab [SCENE]` opens a GLFW window running the same Renderer as the
// headless path, with ImGui panels that only edit the Settings struct.
#include "camera_controller.h"
#include "commands.h"
#include "gl/debug_output.h"
#include "render_target.h"
#include "scenes/gltf_loader.h"
#include "renderer.h"
#include "stats_panel.h"
#include "view_setup.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <CLI/CLI.hpp>

#include <chrono>
#include <ctime>
#include <iostream>
#include <memory>

namespace shadowlab::app {

namespace {

struct ViewerOptions {
    std::string scene;
    int frames = 0;  // 0 = run until closed
    std::string screenshot;  // written after the last frame
    int width = 1280, height = 720;
    SettingsOverrides overrides;
};

// Files dropped on the window, loaded at the start of the next frame.
std::vector<std::string> g_droppedFiles;

void onDrop(GLFWwindow*, int count, const char** paths) {
    for (int i = 0; i < count; ++i) g_droppedFiles.emplace_back(paths[i]);
}

struct WindowDeleter {
    void operator()(GLFWwindow* w) const { glfwDestroyWindow(w); }
};

// Terminates GLFW however the viewer leaves.
struct GlfwSession {
    bool ok = glfwInit() == GLFW_TRUE;
    ~GlfwSession() {
        if (ok) glfwTerminate();
    }
};

struct ImGuiSession {
    explicit ImGuiSession(GLFWwindow* window) {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;  // the view state is saved as JSON instead
        ImGui::StyleColorsDark();
        ImGui_ImplGlfw_InitForOpenGL(window, true);
        ImGui_ImplOpenGL3_Init("#version 450");
    }
    ~ImGuiSession() {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
};

std::string screenshotName(const Settings& settings) {
    std::time_t now = std::time(nullptr);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
    return std::string("shadowlab-") + methodName(settings.method) + "-" + stamp + ".png";
}

CameraInput readCameraInput(GLFWwindow* window, double dt, glm::dvec2& lastCursor, double& scrollAccumulator) {
    CameraInput in;
    in.dt = dt;
    glm::dvec2 cursor;
    glfwGetCursorPos(window, &cursor.x, &cursor.y);
    const glm::dvec2 delta = cursor - lastCursor;
    lastCursor = cursor;
    const ImGuiIO& io = ImGui::GetIO();
    in.scroll = io.WantCaptureMouse ? 0.0 : scrollAccumulator;
    scrollAccumulator = 0.0;
    if (!io.WantCaptureMouse) {
        if (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS) in.lookDelta = delta;
        if (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS) in.orbitDelta = delta;
    }
    if (!io.WantCaptureKeyboard) {
        auto key = [&](int k) { return glfwGetKey(window, k) == GLFW_PRESS ? 1.0 : 0.0; };
        in.move = {key(GLFW_KEY_D) - key(GLFW_KEY_A), key(GLFW_KEY_E) - key(GLFW_KEY_Q), key(GLFW_KEY_W) - key(GLFW_KEY_S)};
        in.fast = key(GLFW_KEY_LEFT_SHIFT) > 0.0;
    }
    return in;
}

double g_scroll = 0.0;
void onScroll(GLFWwindow* window, double dx, double dy) {
    ImGui_ImplGlfw_ScrollCallback(window, dx, dy);
    g_scroll += dy;
}

void runViewer(const ViewerOptions& options) {
    const std::string sceneFile = options.scene.empty() ? defaultScenePath() : options.scene;
    std::optional<Scene> scene = loadSceneReporting(sceneFile);
    if (!scene) throw CLI::RuntimeError(1);
    Settings settings = initialSettings(*scene);
    std::string error;
    if (!applyOverrides(settings, options.overrides, error)) {
        std::cerr << "shadowlab: " << error << "\n";
        throw CLI::RuntimeError(1);
    }

    GlfwSession glfw;
    if (!glfw.ok) {
        std::cerr << "shadowlab: cannot initialise GLFW (no display? use `shadowlab render` headless)\n";
        throw CLI::RuntimeError(1);
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
    glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_TRUE);
    std::unique_ptr<GLFWwindow, WindowDeleter> window(
        glfwCreateWindow(options.width, options.height, "shadowlab", nullptr, nullptr));
    if (!window) {
        std::cerr << "shadowlab: cannot open an OpenGL 4.5 core window\n";
        throw CLI::RuntimeError(1);
    }
    glfwMakeContextCurrent(window.get());
    glfwSwapInterval(options.frames > 0 ? 0 : 1);
    glfwSetDropCallback(window.get(), onDrop);

    gl::DebugLog debugLog;
    gl::installDebugOutput(debugLog);
    auto renderer = Renderer::create(error);
    if (!renderer) {
        std::cerr << "shadowlab: " << error << "\n";
        throw CLI::RuntimeError(1);
    }
    renderer->setScene(*scene);
    ImGuiSession imgui(window.get());
    glfwSetScrollCallback(window.get(), onScroll);

    ui::ViewerStatus status;
    status.sceneName = sceneFile;
    status.sceneTriangles = scene->triangleCount();
    status.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    CameraController controller;
    controller.orbitDistance = std::max(1.0, glm::length(scene->bounds.extent()) * 0.25);
    glm::dvec2 lastCursor{0.0};
    glfwGetCursorPos(window.get(), &lastCursor.x, &lastCursor.y);

    using Clock = std::chrono::steady_clock;
    auto last = Clock::now();
    double fps = 0.0, seconds = 0.0;
    FrameStats stats;
    bool screenshotRequested = false;
    for (int frame = 0; !glfwWindowShouldClose(window.get()); ++frame) {
        if (options.frames > 0 && frame >= options.frames) break;
        glfwPollEvents();
        const auto now = Clock::now();
        const double dt = std::chrono::duration<double>(now - last).count();
        last = now;
        seconds += dt;
        if (dt > 0.0) fps = fps == 0.0 ? 1.0 / dt : fps * 0.95 + 0.05 / dt;

        for (const std::string& file : std::exchange(g_droppedFiles, {})) {
            LoadResult loaded = loadScene(file);
            if (!loaded.ok()) {
                status.lastError = loaded.error;  // keep the current scene
                std::cerr << "shadowlab: " << loaded.error << "\n";
                continue;
            }
            scene = std::move(loaded.scene);
            settings.camera = initialSettings(*scene).camera;
            renderer->setScene(*scene);
            status = {file, scene->triangleCount(), status.renderer, "", "opened " + file};
            controller.orbitDistance = std::max(1.0, glm::length(scene->bounds.extent()) * 0.25);
        }

        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        if (ImGui::IsKeyPressed(GLFW_KEY_F12, false)) screenshotRequested = true;
        controller.apply(settings.camera, readCameraInput(window.get(), dt, lastCursor, g_scroll));

        const auto cpuStart = Clock::now();
        int fbWidth = 0, fbHeight = 0;
        glfwGetFramebufferSize(window.get(), &fbWidth, &fbHeight);
        if (fbWidth > 0 && fbHeight > 0)
            stats = renderer->render(*scene, settings, seconds, Viewport{0, 0, 0, fbWidth, fbHeight});
        const double frameCpuMs = std::chrono::duration<double, std::milli>(Clock::now() - cpuStart).count();

        ui::drawStatsPanel(stats, fps, frameCpuMs, status);
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

        const bool lastFrame = options.frames > 0 && frame + 1 >= options.frames;
        if (screenshotRequested || (lastFrame && !options.screenshot.empty())) {
            const std::string file = lastFrame && !options.screenshot.empty() ? options.screenshot : screenshotName(settings);
            RgbaImage shot = readFramebuffer(0, 0, 0, fbWidth, fbHeight);
            if (writePng(shot, file, error)) status.lastMessage = "saved " + file;
            else status.lastError = error;
            std::cerr << "shadowlab: " << (status.lastError.empty() ? status.lastMessage : status.lastError) << "\n";
            screenshotRequested = false;
        }
        glfwSwapBuffers(window.get());
    }
    if (debugLog.errorCount > 0) {
        std::cerr << "shadowlab: " << debugLog.errorCount << " OpenGL error(s)\n";
        throw CLI::RuntimeError(2);
    }
}

}  // namespace

void addViewerOptions(CLI::App& app) {
    auto options = std::make_shared<ViewerOptions>();
    app.add_option("scene", options->scene, "glTF scene to open (.gltf/.glb); default: the generated forest");
    app.add_option("--frames", options->frames, "run this many frames, then exit (0 = until closed)");
    app.add_option("--screenshot", options->screenshot, "save the last frame (with panels) to this PNG");
    app.add_option("--width", options->width, "window width")->capture_default_str();
    app.add_option("--height", options->height, "window height")->capture_default_str();
    app.add_option("--view", options->overrides.viewFile, "view state JSON (camera, light, all settings)");
    app.add_option("--method", options->overrides.method, "ssm, ssm-unfocused, psm or lispsm");
    app.add_option("--set", options->overrides.sets, "a setting as key=value (repeatable)");
    // Runs when no sub-command was given.
    app.callback([&app, options] {
        if (app.get_subcommands().empty()) runViewer(*options);
    });
}

}  // namespace shadowlab::app
