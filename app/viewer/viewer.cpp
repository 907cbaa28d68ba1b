// The interactive viewer: `shadowlab [SCENE]` opens a GLFW window running the same Renderer as the
// headless path, with ImGui panels that only edit the Settings struct (ui/), overlays drawn by
// OverlayRenderer (renderer/overlays/overlay.h), split compare views and the glTF animations.
//
// Controls (also in the "keys and mouse" help of the View state panel): left drag looks, right drag
// orbits the scene centre, wheel dollies, W/A/S/D/Q/E fly (shift: faster; +/- or the wheel while
// flying change the speed), G walks on the ground, Home/F frames the scene, R returns to the scene's camera, 1-4 pick SSM / SSM unfocused / PSM / LiSPSM, space plays/pauses,
// F1 hides the panels, F12 saves a screenshot; dragging or scrolling over the observer inset turns
// and zooms the observer. File > Open or dropping a file opens a scene (.gltf/.glb), applies a view
// state (.json) or the settings embedded in a shadowlab screenshot (.png).
//
// Input arrives as events (viewer_input.h), scenes load on a worker thread (scene_loading.h), and an
// idle window waits for events instead of redrawing (see the wait in the loop).
#include "commands.h"
#include "gl/debug_output.h"
#include "image/png_text.h"
#include "notifications.h"
#include "resources/render_target.h"
#include "screen_overlays.h"
#include "scenes/animation.h"
#include "settings/method_choice.h"
#include "ground_probe.h"
#include "viewer/viewer_clock.h"
#include "viewer/viewer_frame.h"
#include "viewer/viewer_open.h"
#include "viewer/viewer_options.h"
#include "widgets.h"
#include "viewer/viewer_window.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <CLI/Error.hpp>

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

// Frames drawn after the last event or setting change before the window goes idle: ImGui settles
// its layout in one or two frames, and the GPU timings of a change are read a few frames late
// (SectionTimer keeps four frames in flight).
constexpr int kSettleFrames = 5;

bool writeTextFile(const std::string& file, const std::string& text, std::string& error) {
    std::ofstream out(file, std::ios::binary);
    if (!out || !(out << text) || !out.flush()) {
        error = "cannot write '" + file + "'";
        return false;
    }
    return true;
}

// Fly speed times 1.25 per step (steps < 0: slower), within the speed slider's range.
void changeFlySpeed(ViewerState& state, double steps) {
    CameraSettings& camera = state.settings.camera;
    camera.moveSpeed = std::clamp(camera.moveSpeed * std::pow(1.25, steps), 0.05, 1000.0);
    state.status.lastMessage = "fly speed " + ui::formatNumber(camera.moveSpeed, 3) + " m/s";
}

// Walk mode on (the eye kept at its present height above the ground under it) or off.
void toggleWalk(ViewerState& state) {
    CameraController& controller = state.controller;
    if (controller.walkOn || !state.scene) {
        controller.walkOn = nullptr;
        state.status.lastMessage = "flying (G walks)";
        return;
    }
    if (!state.ground) state.ground.emplace(*state.scene);  // indexed once per scene
    const glm::dvec3 eye = state.settings.camera.position;
    const std::optional<double> ground = state.ground->below(eye.x, eye.z, eye.y);
    if (!ground) {
        state.status.lastMessage = "no ground under the camera to walk on";
        return;
    }
    controller.walkEyeHeight = std::max(0.05, eye.y - *ground);
    controller.walkOn = &*state.ground;
    state.status.lastMessage =
        "walking, the eye " + ui::formatNumber(controller.walkEyeHeight, 3) + " m above the ground (G flies)";
}

void runAction(ViewerState& state, ViewerAction action, double aspect) {
    if (applyMethodAction(action, state.settings)) return;
    switch (action) {
        case ViewerAction::FlyFaster: changeFlySpeed(state, 1.0); break;
        case ViewerAction::FlySlower: changeFlySpeed(state, -1.0); break;
        case ViewerAction::ToggleWalk: toggleWalk(state); break;
        case ViewerAction::TogglePlay: state.settings.animation.playing = !state.settings.animation.playing; break;
        case ViewerAction::ToggleUi: state.showUi = !state.showUi; break;
        case ViewerAction::Screenshot: state.screenshotRequested = true; break;
        case ViewerAction::FrameScene:
            if (state.scene) state.settings.camera = framedCamera(state.settings.camera, state.scene->bounds, aspect);
            break;
        case ViewerAction::ResetCamera:
            if (state.scene) state.settings.camera = initialSettings(*state.scene).camera;
            break;
        default: break;
    }
}

// Window coordinates to framebuffer pixels (they differ on HiDPI screens).
glm::dvec2 toFramebuffer(GLFWwindow* window, const glm::dvec2& p) {
    int fbWidth = 1, fbHeight = 1, winWidth = 1, winHeight = 1;
    glfwGetFramebufferSize(window, &fbWidth, &fbHeight);
    glfwGetWindowSize(window, &winWidth, &winHeight);
    return {p.x * fbWidth / std::max(1, winWidth), p.y * fbHeight / std::max(1, winHeight)};
}

// Turns this frame's events into actions, drags and wheel steps, in the order they happened.
void handleInput(ViewerState& state, std::vector<InputEvent> events, GLFWwindow* window, const Layout& layout) {
    const ImGuiIO& io = ImGui::GetIO();  // what ImGui wanted at the end of the last frame
    // The mouse belongs to ImGui where a panel lies under the cursor at the time of the event (not
    // where it lay at the end of the last frame), while a widget is being dragged, or a popup is open.
    auto panelWantsMouse = [&] {
        const glm::dvec2 p = state.drag.cursor();
        return ui::panelAt(ImVec2(float(p.x), float(p.y))) || ImGui::IsAnyItemActive() ||
               ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId);
    };
    const double aspect = layout.views.empty() ? 1.0 : double(layout.views[0].width) / layout.views[0].height;
    auto insetUnderCursor = [&] {
        const glm::dvec2 p = toFramebuffer(window, state.drag.cursor());
        return insetAt(layout, p.x, p.y);
    };
    auto overObserver = [&] { return insetUnderCursor() == InsetKind::Observer; };
    for (const InputEvent& e : events) {
        switch (e.kind) {
            case InputKind::Key: {
                if (!io.WantCaptureKeyboard || e.action == GLFW_RELEASE) state.fly.onKey(e.code, e.action, e.mods, e.time);
                if (e.action != GLFW_PRESS) break;
                const ViewerAction action = actionForKey(e.code, e.mods);
                if (!io.WantCaptureKeyboard || actsWhileTyping(action)) runAction(state, action, aspect);
                break;
            }
            case InputKind::MouseButton:
                if (e.action == GLFW_RELEASE) {
                    // A click (no drag) on an inset enlarges it, or shrinks it back.
                    const bool click = state.drag.onRelease();
                    const InsetKind pressed = std::exchange(state.pressedInset, InsetKind::None);
                    if (click && e.code == GLFW_MOUSE_BUTTON_LEFT && pressed != InsetKind::None &&
                        insetUnderCursor() == pressed)
                        state.enlargedInset = state.enlargedInset == pressed ? InsetKind::None : pressed;
                    // Ctrl+click on the scene: that object casts or stops casting (caster model).
                    else if (click && e.code == GLFW_MOUSE_BUTTON_LEFT && (e.mods & GLFW_MOD_CONTROL) &&
                             pressed == InsetKind::None && !io.WantCaptureMouse)
                        pickCaster(state, layout, toFramebuffer(window, state.drag.cursor()));
                } else if (e.code == GLFW_MOUSE_BUTTON_LEFT || e.code == GLFW_MOUSE_BUTTON_RIGHT) {
                    const bool panel = panelWantsMouse();
                    state.pressedInset = panel ? InsetKind::None : insetUnderCursor();
                    const DragTarget target = panel ? DragTarget::None
                                              : overObserver()    ? DragTarget::Observer
                                              : e.code == GLFW_MOUSE_BUTTON_LEFT ? DragTarget::Look
                                                                                 : DragTarget::Orbit;
                    state.drag.onPress(target);
                }
                break;
            case InputKind::CursorMove: state.drag.onCursor(e.position); break;
            case InputKind::Scroll:
                if (panelWantsMouse()) break;
                if (state.fly.anyHeld() || state.drag.target() == DragTarget::Look)
                    changeFlySpeed(state, e.scroll);  // while flying, the wheel sets the speed
                else if (overObserver())
                    state.observer.distance = std::clamp(state.observer.distance * std::pow(0.9, e.scroll), 0.3, 5.0);
                else
                    state.scroll += e.scroll;
                break;
        }
    }
}

CameraInput cameraInput(ViewerState& state) {
    CameraInput in;
    in.flight = state.fly.takeFlight(glfwGetTime());
    in.fast = state.fly.fast();
    in.scroll = std::exchange(state.scroll, 0.0);
    const DragDeltas drag = state.drag.takeDeltas();
    in.lookDelta = drag.look;
    in.orbitDelta = drag.orbit;
    state.observer.yawDeg = std::remainder(state.observer.yawDeg + drag.observer.x * 0.4, 360.0);
    state.observer.pitchDeg = std::clamp(state.observer.pitchDeg + drag.observer.y * 0.4, -10.0, 89.0);
    return in;
}

// The control window and what its buttons ask for.
void drawPanels(ViewerState& state, int fbWidth, int fbHeight) {
    // The z_f the auto mode picked last frame (thesis 9.2.5: the farthest visible depth from
    // the renderer's depth pre-pass), for the LiSPSM panel's slider.
    static const Scene kNoScene{};
    state.accuracy.view.stale = state.accuracy.view.measured && !stillMeasured(state.accuracy, state.settings);
    ui::ControlContext ctx{&state.stats,    state.scene ? &*state.scene : &kNoScene, state.animation,
                           state.stats.virtualFarUsed, &state.observer, &state.viewState, &state.file,
                           &state.accuracy.view, &state.accuracy.toggles};
    ctx.ab = &state.ab;
    // Split compare: the read-outs of the view that shows the method, not of the left view.
    const std::vector<MethodChoice> shown = ui::shownMethods(state.settings);
    for (std::size_t i = 0; i < shown.size() && i < state.paneStats.size() && !state.ab.active; ++i) {
        if (shown[i].cascaded) continue;  // the LiSPSM / PSM panels read out one map
        if (shown[i].method == ShadowMethod::Lispsm && !ctx.lispsmStats) ctx.lispsmStats = &state.paneStats[i];
        if (shown[i].method == ShadowMethod::Psm && !ctx.psmStats) ctx.psmStats = &state.paneStats[i];
    }
    const ui::ControlResult controls = ui::drawControlWindow(state.settings, ctx, float(fbWidth), float(fbHeight));
    state.panelCollapsed = controls.collapsed;
    if (controls.changed) addNotices(state.status, sanitize(state.settings));
    if (controls.requests.save) {
        const std::string file = state.viewState.file;
        std::string error;
        if (writeTextFile(file, toJsonText(state.settings), error))
            state.status.lastMessage = "saved view " + file;
        else
            state.status.lastError = error;
    }
    if (!controls.openFile.empty()) openFile(state, controls.openFile);
    if (controls.requests.screenshot) state.screenshotRequested = true;
    if (controls.accuracy.measure) state.accuracy.requested = true;
}

// A screenshot carries the settings it was rendered with in a PNG tEXt chunk (renderer/image/png_text.h)
// and, when `jsonBeside`, as FILE.json next to it: dropping it on the viewer or `shadowlab render
// --view shot.png` reproduces the image. The PNG also names the scene and the size of the 3D view (ShotOrigin, app/view_setup.h), so
// `render --view shot.png` needs neither.
void saveScreenshot(ViewerState& state, const RgbaImage& shot, const std::string& file, bool jsonBeside,
                    const InsetRect& view) {
    std::string error;
    const std::string json = toJsonText(state.settings);
    std::error_code ec;
    const ShotOrigin origin{view.width, view.height, state.status.sceneName,
                            std::filesystem::absolute(state.status.sceneName, ec).string(), state.sceneHash};
    if (!writePng(shot, file, error) || !addPngTextToFile(file, kSettingsPngKeyword, json, error) ||
        !writeShotOrigin(file, origin, error)) {
        state.status.lastError = error;
    } else {
        const std::filesystem::path path = std::filesystem::absolute(file, ec);
        state.status.lastMessage = "saved " + path.filename().string() + " (" + std::to_string(shot.width) + "x" +
                                   std::to_string(shot.height) + ") in " + path.parent_path().string();
        if (jsonBeside) {
            const std::string beside = std::filesystem::path(file).replace_extension(".json").string();
            if (writeTextFile(beside, json, error))
                state.status.lastMessage += ", settings also in " + std::filesystem::path(beside).filename().string();
            else state.status.lastError = error;
        }
    }
    std::cerr << "shadowlab: " << (error.empty() ? state.status.lastMessage : error) << "\n";
}

// The Stats window's line on how the camera moves and how to change it.
std::string navigationLine(const ViewerState& state) {
    const std::string speed = ui::formatNumber(state.settings.camera.moveSpeed, 3) + " m/s";
    if (state.controller.walkOn)
        return "walk " + speed + ", eye " + ui::formatNumber(state.controller.walkEyeHeight, 3) + " m: +/-; G flies";
    return "fly " + speed + ": +/- or wheel while flying; G walks";
}

void updateTitle(GLFWwindow* window, const ViewerState& state, std::string& windowTitle) {
    // The title names the scene and the method(s) on screen.
    std::string title = "shadowlab - " + std::filesystem::path(state.status.sceneName).filename().string() + " - ";
    for (const Pane& pane : splitPanes(state.settings))  // "csm-lispsm" for cascades
        title += std::string(title.back() == ' ' ? "" : " | ") + methodChoiceName(methodChoiceOf(pane.settings));
    if (title != windowTitle) glfwSetWindowTitle(window, (windowTitle = title).c_str());
}

// Adds or removes the ground plane when display.groundPlane changed (and re-uploads the scene).
void syncGroundPlane(ViewerState& state, Renderer& renderer) {
    if (!state.scene || state.settings.display.groundPlane == state.groundPlane.has_value()) return;
    if (state.groundPlane) {
        removeGroundPlane(*state.scene, *state.groundPlane);
        state.groundPlane.reset();
    } else {
        state.groundPlane = addGroundPlane(*state.scene);
    }
    state.ground.reset();  // walk mode stands on the plane (or no longer) from now on
    if (state.controller.walkOn) state.controller.walkOn = &state.ground.emplace(*state.scene);
    renderer.setScene(*state.scene, true);  // a re-upload streams its textures too
    state.texturesTotal = state.texturesPending = state.scene->textures.size();
    state.status.sceneTriangles = state.scene->triangleCount();
}

}  // namespace

void runViewer(const ViewerOptions& options) {
    const std::string sceneFile = options.scene.empty() ? defaultScenePath() : options.scene;
    std::string error;
    {
        // Bad --view / --set values are refused before a window opens (a bad scene is not: the
        // window shows its error over the default scene).
        Settings probe;
        LoadOptions load;
        if (!applyOverrides(probe, options.overrides, error) || !applyLoadLimits(load, options.limits, error)) {
            std::cerr << "shadowlab: " << error << "\n";
            throw CLI::RuntimeError(1);
        }
    }
    GlfwSession glfw;
    if (!glfw.ok) {
        std::cerr << "shadowlab: cannot initialise GLFW (no display? use `shadowlab render` headless)\n";
        throw CLI::RuntimeError(1);
    }
    WindowPtr window = createViewerWindow(options.width, options.height);
    if (!window) {
        std::cerr << "shadowlab: cannot open an OpenGL 4.5 core window\n";
        throw CLI::RuntimeError(1);
    }
    glfwMakeContextCurrent(window.get());
    glfwSwapInterval(options.frames > 0 ? 0 : 1);
    WindowEvents events;
    installWindowCallbacks(window.get(), events);

    gl::DebugLog debugLog;
    gl::installDebugOutput(debugLog);
    auto renderer = Renderer::create(error);
    auto overlays = renderer ? OverlayRenderer::create(error) : nullptr;
    if (!renderer || !overlays) {
        std::cerr << "shadowlab: " << error << "\n";
        throw CLI::RuntimeError(1);
    }
    SectionTimer sectionTimer(kFrameSections);
    AbTargets abTargets;
    ImGuiSession imgui(window.get());

    ViewerState state;
    state.showUi = !options.noUi;
    applyLoadLimits(state.loadOptions, options.limits, error);  // checked above
    if (!requestedScene(options.overrides, state.loadOptions, error)) {
        std::cerr << "shadowlab: " << error << "\n";
        throw CLI::RuntimeError(1);
    }
    state.abView = options.abView;
    if (options.abMode == "wipe") state.ab.mode = ui::AbMode::Wipe;
    else if (options.abMode == "diff") state.ab.mode = ui::AbMode::Difference;
    else if (options.abMode != "side") {
        std::cerr << "shadowlab: --ab-mode is side, wipe or diff\n";
        throw CLI::RuntimeError(1);
    }
    state.status.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    startSceneLoad(state, sceneFile);
    warmUpTextureUploads();  // while the worker parses

    using Clock = std::chrono::steady_clock;
    auto last = Clock::now();
    double fps = 0.0;
    std::string windowTitle;
    int framesOwed = kSettleFrames;
    bool animationShows = true;  // the last step of a playing animation changed the picture
    for (int frame = 0; !glfwWindowShouldClose(window.get());) {
        // Idle: wait for an event (a load finishing posts one) instead of redrawing an unchanged
        // frame; a software rasteriser would spend a whole core on it.
        // A playing animation draws only while a step changes the picture (viewer_clock.h); off
        // screen it is posed at kOffscreenAnimationPollSeconds between waits.
        const bool playing = animating(state);
        const bool inputOrLoad = options.frames > 0 || state.fly.anyHeld() ||
                                 state.drag.target() != DragTarget::None || state.uploadNext || state.texturesPending > 0;
        // The visible-depth result arrives next frame.
        const bool readbackOnly = !inputOrLoad && renderer->readbackPending();
        const bool mustDraw = inputOrLoad || readbackOnly;
        if (mustDraw || framesOwed > 0 || (playing && animationShows)) glfwPollEvents();
        else if (state.load || ui::notificationsFading(state.status))
            glfwWaitEventsTimeout(0.1);  // the progress bar moves, a message fades
        else if (playing) glfwWaitEventsTimeout(kOffscreenAnimationPollSeconds);
        else glfwWaitEvents();
        std::vector<InputEvent> input = events.input.drain();
        if (!input.empty() || !events.droppedFiles.empty() || std::exchange(events.exposed, false))
            framesOwed = kSettleFrames;

        const auto now = Clock::now();
        // Clamped: the first frame after an idle wait must not animate by the wait (flight is
        // integrated on the keys' own times, FlyKeys).
        const double dt = std::min(0.25, std::chrono::duration<double>(now - last).count());
        last = now;

        if (state.uploadNext) {
            finishSceneLoad(state, *renderer, options.overrides);
            state.texturesPending = state.texturesTotal;
            framesOwed = kSettleFrames;
        } else if (state.texturesPending > 0) {
            // A texture or two per frame (one 1024^2 with mipmaps: ~14 ms on llvmpipe).
            constexpr double kTextureBudgetMs = 20.0;
            const auto start = Clock::now();
            state.texturesPending = renderer->streamTextures(kTextureBudgetMs);
            state.textureFrames.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
            if (state.texturesPending == 0) {
                framesOwed = kSettleFrames;
                const auto& ms = state.textureFrames;
                std::cerr << "shadowlab: textures uploaded over " << ms.size() << " frames, at most "
                          << ui::formatNumber(*std::max_element(ms.begin(), ms.end()), 3) << " ms per frame\n";
                state.textureFrames.clear();
            }
        }
        state.uploadNext = state.load && state.load->done();
        for (const std::string& file : std::exchange(events.droppedFiles, {})) openFile(state, file);
        reloadForSceneIndex(state);
        // Nothing but the animation asks for a frame: pose on the CPU, draw only what shows.
        double clockDt = dt;
        bool holdPose = false;
        if (playing && !inputOrLoad && framesOwed == 0 && input.empty() && !state.uploadNext && !state.load &&
            !ui::notificationsFading(state.status) && state.scene) {
            animationShows = stepClockShows(state, dt);
            clockDt = 0.0;  // stepped already
            // A readback in flight is taken by one more frame at the pose the GPU has, so the scene
            // it measured is still the scene (a new pose would start another readback each frame).
            if (!animationShows && !readbackOnly) continue;
            holdPose = !animationShows;
        }

        int fbWidth = 0, fbHeight = 0;
        glfwGetFramebufferSize(window.get(), &fbWidth, &fbHeight);
        handleInput(state, std::move(input), window.get(),
                    layoutFrame(fbWidth, fbHeight, state.showUi && !state.panelCollapsed, state.settings,
                                int(framePanes(state.ab, state.settings).size()), state.enlargedInset));
        const Settings before = state.settings;

        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        if (state.showUi) drawPanels(state, fbWidth, fbHeight);
        const std::vector<Pane> panes = framePanes(state.ab, state.settings);
        const Layout layout =
            layoutFrame(fbWidth, fbHeight, state.showUi && !state.panelCollapsed, state.settings, int(panes.size()), state.enlargedInset);
        if (state.scene) state.controller.apply(state.settings.camera, cameraInput(state));
        updateTitle(window.get(), state, windowTitle);

        double timeBeforeClock = state.settings.animation.time;
        const auto cpuStart = Clock::now();
        std::vector<ui::Caption> captions;
        ViewsResult views;
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, std::max(1, fbWidth), std::max(1, fbHeight));
        if (state.scene && fbWidth > 0 && fbHeight > 0) {
            syncGroundPlane(state, *renderer);
            timeBeforeClock = state.settings.animation.time;
            advanceClock(state, *renderer, clockDt, !holdPose);
            if (abComposites(state.ab)) {
                glBindFramebuffer(GL_FRAMEBUFFER, 0);
                const GLfloat clear[4] = {0.08f, 0.08f, 0.09f, 1.0f};
                glClearBufferfv(GL_COLOR, 0, clear);
                views.stats = drawAbComposite(*renderer, *state.scene, state.settings, layout, state.ab, abTargets,
                                              views.captions);
            } else {
                views = drawViews({*renderer, *overlays, sectionTimer}, *state.scene, panes, layout, state.observer,
                                  toFramebuffer(window.get(), state.drag.cursor()));
            }
            state.stats = views.stats;
            state.paneStats = views.paneStats;
            watchFrame(state, panes.front().settings, int(panes.size()),
                       double(layout.views[0].width) / std::max(1, layout.views[0].height), *renderer);
            if (std::exchange(state.accuracy.requested, false))
                measureForPanel(state.accuracy, *renderer, *state.scene, state.settings, layout.views[0].width,
                                layout.views[0].height);
        } else {
            const GLfloat clear[4] = {0.08f, 0.08f, 0.09f, 1.0f};
            glClearBufferfv(GL_COLOR, 0, clear);
        }
        const double frameCpuMs = std::chrono::duration<double, std::milli>(Clock::now() - cpuStart).count();

        ui::LoadingInfo loading;
        if (state.load)
            loading = {true, state.load->file(), state.load->secondsRunning(), state.uploadNext, state.load->progress()};
        else if (state.texturesPending > 0)
            loading = {true, state.status.sceneName, 0.0, false,
                       1.0 - double(state.texturesPending) / double(std::max<std::size_t>(1, state.texturesTotal)), true};
        const float belowNotifications =
            ui::drawNotifications(state.status, loading, 0.0f, float(layout.viewWidth), glfwGetTime());
        // F12 without panels: the rendered 3D area as it is now, before any ImGui drawing.
        std::optional<RgbaImage> bareShot;
        if (state.screenshotRequested && !state.viewState.screenshotPanels && fbWidth > 0 && fbHeight > 0)
            bareShot = readFramebuffer(0, 0, 0, layout.viewWidth, fbHeight);
        // Captions (method names, inset titles, error numbers) belong to the image: they stay with F1.
        addErrorCaptions(views, layout, toFramebuffer(window.get(), state.drag.cursor()), views.captions);
        ui::drawCaptions(views.captions);
        if (state.settings.viewMode == ViewMode::AliasingError)
            ui::drawHeatLegendWindow(float(layout.viewWidth), belowNotifications);
        if (state.scene && !layout.views.empty())
            drawMismatchOverlay(state.accuracy, state.settings, float(layout.views[0].x), float(layout.views[0].y),
                                float(layout.views[0].width), float(layout.views[0].height));
        if (state.showUi) {
            // Split compare began: fold the stats window so it does not cover the left view.
            // Not in A/B compare: storing A is no reason to hide the figures.
            state.status.collapseStats = views.paneStats.size() > 1 && !state.ab.active &&
                                         std::exchange(state.splitShown, true) == false;
            if (views.paneStats.size() <= 1) state.splitShown = false;
            state.status.compareLines = views.compareLines;
            state.status.navigation = navigationLine(state);
            ui::drawStatsPanel(state.stats, fps, frameCpuMs, state.status, statsArea(layout, belowNotifications));
        }
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

        const InsetRect shotView = layout.views.empty() ? InsetRect{} : layout.views[0];
        // --frames counts frames of a scene (or of the error, when none could be loaded).
        const bool counting = options.frames > 0 && !state.load && !state.uploadNext;
        const bool lastFrame = counting && frame + 1 >= options.frames;
        if (lastFrame && !options.screenshot.empty())  // --screenshot: the window as shown, panels and all
            saveScreenshot(state, readFramebuffer(0, 0, 0, fbWidth, fbHeight), options.screenshot, false, shotView);
        if (std::exchange(state.screenshotRequested, false))
            saveScreenshot(state, bareShot ? *bareShot : readFramebuffer(0, 0, 0, fbWidth, fbHeight),
                           ui::screenshotFileName(state.settings, std::time(nullptr)), true, shotView);
        glfwSwapBuffers(window.get());
        // The rate the viewer draws at: the frame's own time, not counting an idle wait for events.
        const double frameSeconds = std::chrono::duration<double>(Clock::now() - now).count();
        if (frameSeconds > 0.0) fps = fps == 0.0 ? 1.0 / frameSeconds : fps * 0.8 + 0.2 / frameSeconds;
        // The clock's own step owes no settle frames (a playing animation would never settle).
        Settings changed = state.settings;
        changed.animation.time = timeBeforeClock;
        if (!(changed == before)) {
            framesOwed = kSettleFrames;
            noteSceneNotices(state);
        }
        framesOwed = std::max(0, framesOwed - 1);
        if (counting && ++frame >= options.frames) break;
    }
    if (!options.saveView.empty()) {
        if (!writeTextFile(options.saveView, toJsonText(state.settings), error)) {
            std::cerr << "shadowlab: " << error << "\n";
            throw CLI::RuntimeError(1);
        }
    }
    if (debugLog.errorCount > 0) {
        std::cerr << "shadowlab: " << debugLog.errorCount << " OpenGL error(s)\n";
        throw CLI::RuntimeError(2);
    }
}

}  // namespace shadowlab::app
