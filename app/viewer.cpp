// The interactive viewer: `shadowlab [SCENE]` opens a GLFW window running the same Renderer as the
// headless path, with ImGui panels that only edit the Settings struct (ui/), overlays drawn by
// OverlayRenderer (renderer/overlay.h), split compare views and the glTF animations.
//
// Controls: left drag looks, right drag orbits, wheel dollies, W/A/S/D/Q/E fly (shift: faster),
// 1-4 pick SSM / SSM unfocused / PSM / LiSPSM, space plays/pauses, F1 hides the panels,
// F12 saves a screenshot named after the method(s); dragging or scrolling over the observer inset
// turns and zooms the observer. Dropping a .json file applies a view state,
// dropping a .gltf/.glb opens it.
#include "camera_controller.h"
#include "commands.h"
#include "gl/debug_output.h"
#include "overlay.h"
#include "overlay_timer.h"
#include "panels.h"
#include "render_target.h"
#include "renderer.h"
#include "scenes/animation.h"
#include "scenes/gltf_loader.h"
#include "stats_panel.h"
#include "widgets.h"
#include "view_setup.h"
#include "view_state.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

namespace shadowlab::app {

namespace {

struct ViewerOptions {
    std::string scene;
    int frames = 0;          // 0 = run until closed
    std::string screenshot;  // written after the last frame
    std::string saveView;    // view state JSON written on exit
    bool noUi = false;       // start with the panels hidden (F1 toggles)
    int width = 1280, height = 720;
    SettingsOverrides overrides;
};

// Files dropped on the window, handled at the start of the next frame.
std::vector<std::string> g_droppedFiles;

void onDrop(GLFWwindow*, int count, const char** paths) {
    for (int i = 0; i < count; ++i) g_droppedFiles.emplace_back(paths[i]);
}

double g_scroll = 0.0;
void onScroll(GLFWwindow* window, double dx, double dy) {
    ImGui_ImplGlfw_ScrollCallback(window, dx, dy);
    g_scroll += dy;
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
        in.move = {key(GLFW_KEY_D) - key(GLFW_KEY_A), key(GLFW_KEY_E) - key(GLFW_KEY_Q),
                   key(GLFW_KEY_W) - key(GLFW_KEY_S)};
        in.fast = key(GLFW_KEY_LEFT_SHIFT) > 0.0;
    }
    return in;
}

bool writeTextFile(const std::string& file, const std::string& text, std::string& error) {
    std::ofstream out(file, std::ios::binary);
    if (!out || !(out << text) || !out.flush()) {
        error = "cannot write '" + file + "'";
        return false;
    }
    return true;
}

// Applies a view-state JSON file to the settings (only when it is valid as a whole).
bool loadViewFile(const std::string& file, Settings& settings, std::string& error) {
    std::string text;
    if (!readTextFile(file, text, error)) return false;
    Settings loaded = settings;
    if (!fromJsonText(text, loaded, error)) {
        error = file + ": " + error;
        return false;
    }
    for (const std::string& change : sanitize(loaded)) std::cerr << "shadowlab: adjusted " << change << "\n";
    settings = loaded;
    return true;
}

ui::AnimationInfo animationInfo(const Scene& scene) {
    ui::AnimationInfo info;
    info.duration = sceneAnimationDuration(scene);
    info.animations = int(scene.animations.size());
    for (const Animation& a : scene.animations) info.channels += int(a.channels.size());
    return info;
}

// Screen layout of one frame, in framebuffer pixels with the origin at the TOP-left (ImGui's);
// toGl() flips a rectangle to GL's bottom-left origin.
struct Layout {
    int fbWidth = 0, fbHeight = 0;
    int viewWidth = 0;             // the 3D area: left of the control window
    std::vector<InsetRect> views;  // top-left origin
    InsetRect shadowMapInset, lightViewInset, observerInset;
};

InsetRect toGl(const InsetRect& r, int fbHeight) { return {r.x, fbHeight - r.y - r.height, r.width, r.height}; }

Layout layoutFrame(int fbWidth, int fbHeight, bool showUi, const Settings& settings) {
    Layout l;
    l.fbWidth = fbWidth;
    l.fbHeight = fbHeight;
    l.viewWidth = showUi ? std::max(16, fbWidth - int(ui::controlWindowWidth())) : fbWidth;
    const int count = int(ui::shownMethods(settings).size());
    for (int i = 0; i < count; ++i) {
        const int x0 = l.viewWidth * i / count, x1 = l.viewWidth * (i + 1) / count;
        l.views.push_back({x0, 0, std::max(1, x1 - x0 - (i + 1 < count ? 2 : 0)), fbHeight});
    }
    // Insets along the bottom edge of the 3D area, left to right, as many as are switched on.
    const int margin = 12;
    const int side = std::max(64, std::min({fbHeight / 3, l.viewWidth / 4, 360}));
    int x = margin;
    const int y = fbHeight - side - margin;
    auto place = [&](InsetRect& r, bool on, int width) {
        if (!on) return;
        r = {x, y, width, side};
        x += width + margin + 4;
    };
    place(l.shadowMapInset, settings.overlays.shadowMapInset, side);
    place(l.lightViewInset, settings.overlays.lightViewInset, side);
    place(l.observerInset, settings.overlays.observerInset, side * 4 / 3);
    return l;
}

struct ViewerState {
    ui::ViewerStatus status;
    ui::ObserverView observer;
    ui::ViewStateUi viewState;
    ui::AnimationInfo animation;
    bool showUi = true;
    bool screenshotRequested = false;
};

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
    auto overlays = OverlayRenderer::create(error);
    if (!overlays) {
        std::cerr << "shadowlab: " << error << "\n";
        throw CLI::RuntimeError(1);
    }
    // GPU time of each split view (sections 0-2) and of the overlays (section 3).
    constexpr int kOverlaySection = 3;
    SectionTimer sectionTimer(4);
    // The pose at the saved time, so a loaded view shows the frame it was saved at.
    animateScene(*scene, settings.animation.time);
    renderer->setScene(*scene);
    ImGuiSession imgui(window.get());
    glfwSetScrollCallback(window.get(), onScroll);

    ViewerState state;
    state.showUi = !options.noUi;
    state.status.sceneName = sceneFile;
    state.status.sceneTriangles = scene->triangleCount();
    state.status.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    state.animation = animationInfo(*scene);
    CameraController controller;
    controller.orbitDistance = std::max(1.0, glm::length(scene->bounds.extent()) * 0.25);
    glm::dvec2 lastCursor{0.0};
    glfwGetCursorPos(window.get(), &lastCursor.x, &lastCursor.y);

    using Clock = std::chrono::steady_clock;
    auto last = Clock::now();
    double fps = 0.0;
    double posedTime = settings.animation.time;
    std::string windowTitle;
    FrameStats stats;
    for (int frame = 0; !glfwWindowShouldClose(window.get()); ++frame) {
        if (options.frames > 0 && frame >= options.frames) break;
        glfwPollEvents();
        const auto now = Clock::now();
        const double dt = std::chrono::duration<double>(now - last).count();
        last = now;
        if (dt > 0.0 && frame > 0) fps = fps == 0.0 ? 1.0 / dt : fps * 0.95 + 0.05 / dt;

        for (const std::string& file : std::exchange(g_droppedFiles, {})) {
            if (std::filesystem::path(file).extension() == ".json") {
                if (loadViewFile(file, settings, error))
                    state.status.lastMessage = "applied view " + file;
                else
                    state.status.lastError = error;
                continue;
            }
            LoadResult loaded = loadScene(file);
            if (!loaded.ok()) {
                state.status.lastError = loaded.error;  // keep the current scene
                std::cerr << "shadowlab: " << loaded.error << "\n";
                continue;
            }
            scene = std::move(loaded.scene);
            settings.camera = initialSettings(*scene).camera;
            settings.animation.time = 0.0;
            animateScene(*scene, 0.0);
            posedTime = 0.0;
            renderer->setScene(*scene);
            state.status.sceneName = file;
            state.status.sceneTriangles = scene->triangleCount();
            state.status.lastError.clear();
            state.status.lastMessage = "opened " + file;
            state.animation = animationInfo(*scene);
            controller.orbitDistance = std::max(1.0, glm::length(scene->bounds.extent()) * 0.25);
        }

        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        const ImGuiIO& io = ImGui::GetIO();
        if (ImGui::IsKeyPressed(GLFW_KEY_F12, false)) state.screenshotRequested = true;
        if (ImGui::IsKeyPressed(GLFW_KEY_F1, false)) state.showUi = !state.showUi;
        if (!io.WantCaptureKeyboard) {
            const ShadowMethod byKey[] = {ShadowMethod::SsmFocused, ShadowMethod::SsmUnfocused, ShadowMethod::Psm,
                                          ShadowMethod::Lispsm};
            for (int k = 0; k < 4; ++k)
                if (ImGui::IsKeyPressed(GLFW_KEY_1 + k, false)) settings.method = byKey[k];
            if (ImGui::IsKeyPressed(GLFW_KEY_SPACE, false)) settings.animation.playing = !settings.animation.playing;
        }

        // The title names the scene and the method(s) on screen.
        std::string title = "shadowlab - " + std::filesystem::path(state.status.sceneName).filename().string() + " - ";
        for (ShadowMethod m : ui::shownMethods(settings))
            title += std::string(title.back() == ' ' ? "" : " | ") + methodName(m);
        if (title != windowTitle) glfwSetWindowTitle(window.get(), (windowTitle = title).c_str());

        int fbWidth = 0, fbHeight = 0;
        glfwGetFramebufferSize(window.get(), &fbWidth, &fbHeight);
        if (state.showUi) {
            // The z_f the auto mode picked last frame (thesis 9.2.5: the farthest visible depth from
            // the renderer's depth pre-pass), for the LiSPSM panel's slider.
            const double autoFar = stats.virtualFarUsed;
            ui::ControlContext ctx{&stats, &*scene, state.animation, autoFar, &state.observer, &state.viewState};
            const ui::ControlResult controls = ui::drawControlWindow(settings, ctx, float(fbWidth), float(fbHeight));
            if (controls.changed) sanitize(settings);
            if (controls.requests.save) {
                const std::string file = state.viewState.file;
                if (writeTextFile(file, toJsonText(settings), error))
                    state.status.lastMessage = "saved view " + file;
                else
                    state.status.lastError = error;
            }
            if (controls.requests.load) {
                if (loadViewFile(state.viewState.file, settings, error))
                    state.status.lastMessage = std::string("loaded view ") + state.viewState.file;
                else
                    state.status.lastError = error;
            }
            if (controls.requests.screenshot) state.screenshotRequested = true;
        }
        CameraInput input = readCameraInput(window.get(), dt, lastCursor, g_scroll);
        {
            // Dragging (either button) or scrolling over the observer inset moves the observer, not
            // the camera. Cursor positions are in window coordinates: scale them to framebuffer pixels.
            const InsetRect obs = layoutFrame(fbWidth, fbHeight, state.showUi, settings).observerInset;
            int winWidth = 1, winHeight = 1;
            glfwGetWindowSize(window.get(), &winWidth, &winHeight);
            const double sx = double(fbWidth) / std::max(1, winWidth), sy = double(fbHeight) / std::max(1, winHeight);
            const double cx = lastCursor.x * sx, cy = lastCursor.y * sy;
            if (!obs.empty() && cx >= obs.x && cx < obs.x + obs.width && cy >= obs.y && cy < obs.y + obs.height) {
                const glm::dvec2 drag = input.lookDelta + input.orbitDelta;
                state.observer.yawDeg = std::remainder(state.observer.yawDeg + drag.x * 0.4, 360.0);
                state.observer.pitchDeg = std::clamp(state.observer.pitchDeg + drag.y * 0.4, -10.0, 89.0);
                state.observer.distance = std::clamp(state.observer.distance * std::pow(0.9, input.scroll), 0.3, 5.0);
                input.lookDelta = input.orbitDelta = glm::dvec2(0.0);
                input.scroll = 0.0;
            }
        }
        controller.apply(settings.camera, input);

        // The scene clock: glTF animations and the animated sun; saved with the view so headless
        // renders reproduce the frame.
        if (settings.animation.playing)
            settings.animation.time = std::max(0.0, settings.animation.time + dt * settings.animation.speed);
        if (settings.animation.time != posedTime && animateScene(*scene, settings.animation.time)) {
            // Moving casters: new instance matrices; the renderer recomputes S, B and the map.
            renderer->updateInstances(*scene);
        }
        posedTime = settings.animation.time;
        const double seconds = settings.animation.time;

        const auto cpuStart = Clock::now();
        std::vector<ui::Caption> captions;
        std::vector<std::string> compareLines;
        if (fbWidth > 0 && fbHeight > 0) {
            const Layout layout = layoutFrame(fbWidth, fbHeight, state.showUi, settings);
            // The area right of the views (under the control window) is cleared once.
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glViewport(0, 0, fbWidth, fbHeight);
            const GLfloat clear[4] = {0.08f, 0.08f, 0.09f, 1.0f};
            glClearBufferfv(GL_COLOR, 0, clear);
            // Right to left, so the left view (whose shadow map and setup the insets and read-outs
            // show) is rendered last.
            const std::vector<ShadowMethod> methods = ui::shownMethods(settings);
            for (int i = int(methods.size()) - 1; i >= 0; --i) {
                Settings view = settings;
                view.method = methods[std::size_t(i)];
                const InsetRect r = toGl(layout.views[std::size_t(i)], fbHeight);
                sectionTimer.begin(i);
                FrameStats viewStats =
                    renderer->render(*scene, view, seconds, Viewport{0, r.x, r.y, r.width, r.height});
                sectionTimer.end(i);
                if (methods.size() > 1) {
                    captions.push_back({float(layout.views[std::size_t(i)].x + 8), 8.0f, methodName(view.method)});
                    compareLines.insert(compareLines.begin(), std::string(methodName(view.method)) + ": GPU " +
                                                                  ui::formatNumber(sectionTimer.lastMs(i), 3) +
                                                                  " ms, casters " +
                                                                  std::to_string(viewStats.castersDrawn) + " (culled " +
                                                                  std::to_string(viewStats.castersCulled) + ")");
                }
                if (i == 0) stats = std::move(viewStats);
            }

            const auto overlayStart = Clock::now();
            sectionTimer.begin(kOverlaySection);
            const ViewFrustum viewFrustum0 =
                viewFrustum(settings.camera, double(layout.views[0].width) / std::max(1, layout.views[0].height));
            const LightFrame light = resolveLight(*scene, settings.light, seconds);
            const bool haveMap = stats.shadowMapSize > 0 && renderer->lastShadowSetup().valid;
            const ShadowSetup& setup = renderer->lastShadowSetup();
            auto noteFor = [&](const InsetRect& r, const std::string& title) {
                captions.push_back({float(r.x + 4), float(r.y + 4), title});
            };
            if (!layout.shadowMapInset.empty()) {
                const InsetRect r = toGl(layout.shadowMapInset, fbHeight);
                overlays->drawFrame(0, r);
                if (haveMap) overlays->drawDepthInset(0, r, renderer->shadowMapTexture(), setup.reverseDepthTest);
                noteFor(layout.shadowMapInset, haveMap ? "shadow map" : "no shadow map");
            }
            if (!layout.lightViewInset.empty()) {
                const InsetRect r = toGl(layout.lightViewInset, fbHeight);
                overlays->drawFrame(0, r);
                if (haveMap && renderer->gpuScene()) {
                    const glm::dmat4& m = setup.worldToShadowClip;  // w > 0 over B by contract
                    overlays->drawScene(0, r, *scene, *renderer->gpuScene(), m, light.direction,
                                        setup.reverseDepthTest);
                    const double marker = 0.02 * std::max(1e-3, glm::length(setup.bodyBounds.extent()));
                    overlays->drawWires(0, r,
                                        overlayWires(setup.diagnostics, settings.overlays, viewFrustum0, scene->bounds,
                                                     light.direction, marker),
                                        m);
                }
                noteFor(layout.lightViewInset, haveMap ? "light view" : "no light view");
            }
            if (!layout.observerInset.empty() && renderer->gpuScene()) {
                const InsetRect r = toGl(layout.observerInset, fbHeight);
                overlays->drawFrame(0, r);
                const ShadowDiagnostics& d = stats.shadow;
                const ObserverCamera observer =
                    observerCamera(d, viewFrustum0, scene->bounds, state.observer.yawDeg, state.observer.pitchDeg,
                                   state.observer.distance, double(r.width) / double(r.height));
                overlays->drawScene(0, r, *scene, *renderer->gpuScene(), observer.viewProjection(), light.direction,
                                    false);
                overlays->drawWires(0, r,
                                    overlayWires(d, settings.overlays, viewFrustum0, scene->bounds, light.direction,
                                                 observer.radius * 0.04),
                                    observer.viewProjection());
                noteFor(layout.observerInset, "observer");
            }
            sectionTimer.end(kOverlaySection);
            sectionTimer.endFrame();
            if (!layout.shadowMapInset.empty() || !layout.lightViewInset.empty() || !layout.observerInset.empty())
                stats.passes.push_back({"overlays",
                                        std::chrono::duration<double, std::milli>(Clock::now() - overlayStart).count(),
                                        sectionTimer.lastMs(kOverlaySection)});
        }
        const double frameCpuMs = std::chrono::duration<double, std::milli>(Clock::now() - cpuStart).count();

        if (state.showUi) {
            ui::drawCaptions(captions);
            state.status.compareLines = compareLines;
            ui::drawStatsPanel(stats, fps, frameCpuMs, state.status);
        }
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

        const bool lastFrame = options.frames > 0 && frame + 1 >= options.frames;
        if (state.screenshotRequested || (lastFrame && !options.screenshot.empty())) {
            const std::string file = lastFrame && !options.screenshot.empty()
                                         ? options.screenshot
                                         : ui::screenshotFileName(settings, std::time(nullptr));
            RgbaImage shot = readFramebuffer(0, 0, 0, fbWidth, fbHeight);
            state.status.lastError.clear();
            if (writePng(shot, file, error))
                state.status.lastMessage = "saved " + file;
            else
                state.status.lastError = error;
            std::cerr << "shadowlab: "
                      << (state.status.lastError.empty() ? state.status.lastMessage : state.status.lastError) << "\n";
            state.screenshotRequested = false;
        }
        glfwSwapBuffers(window.get());
    }
    if (!options.saveView.empty()) {
        if (!writeTextFile(options.saveView, toJsonText(settings), error)) {
            std::cerr << "shadowlab: " << error << "\n";
            throw CLI::RuntimeError(1);
        }
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
    app.add_option("--save-view", options->saveView, "write the view state JSON (what --view reads) on exit");
    app.add_flag("--no-ui", options->noUi, "start with the panels hidden (F1 toggles them)");
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
