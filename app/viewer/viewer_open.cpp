#include "viewer/viewer_open.h"

#include "frame/caster_model.h"
#include "scenes/animation.h"

#include <GLFW/glfw3.h>

#include "widgets.h"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <utility>

namespace shadowlab::app {

namespace {

ui::AnimationInfo animationInfo(const Scene& scene) {
    ui::AnimationInfo info;
    info.duration = sceneAnimationDuration(scene);
    for (const Animation& a : scene.animations) info.clips.push_back({a.name, animationDuration(a)});
    info.animations = int(scene.animations.size());
    for (const Animation& a : scene.animations) info.channels += int(a.channels.size());
    return info;
}

// Applies a view state (JSON, or the settings embedded in a screenshot) as a whole or not at all.
void applyViewFile(ViewerState& state, const std::string& file) {
    // A screenshot of another scene would put the camera somewhere meaningless here.
    if (const std::optional<ShotOrigin> origin = readShotOrigin(file); origin && state.scene) {
        const std::string mismatch = sceneMismatch(file, *origin, state.status.sceneName, state.sceneHash);
        if (!mismatch.empty()) {
            state.status.lastError = mismatch;
            std::cerr << "shadowlab: " << mismatch << "\n";
            return;
        }
    }
    Settings loaded = state.settings;
    std::string error;
    if (!readViewFile(file, loaded, error)) {
        state.status.lastError = error;
        std::cerr << "shadowlab: " << error << "\n";
        return;
    }
    addNotices(state.status, sanitize(loaded));
    state.settings = loaded;
    state.status.lastError.clear();
    state.status.lastMessage = "applied view " + file;
    state.file.remember(file);
}

// The settings of the command line's scene: the scene's own, the overrides, then --ab's A.
void applyInitialSettings(ViewerState& state, const Scene& scene, const SettingsOverrides& overrides) {
    state.settings = initialSettings(scene);
    std::string error;
    if (!applyOverrides(state.settings, overrides, error)) state.status.lastError = error;
    if (state.abView.empty()) return;
    Settings a = state.settings;  // A is the command line's settings with that view state on top
    if (readViewFile(state.abView, a, error)) {
        state.ab.a = a;
        state.ab.active = true;
    } else {
        state.status.lastError = error;
    }
}

}  // namespace

void addNotices(ui::ViewerStatus& status, const std::vector<std::string>& changes, const std::string& prefix) {
    for (const std::string& change : changes) {
        std::cerr << "shadowlab: " << prefix << change << "\n";
        status.notices.push_back(prefix + change);
    }
    constexpr std::size_t kMaxNotices = 6;
    if (status.notices.size() > kMaxNotices)
        status.notices.erase(status.notices.begin(), status.notices.end() - kMaxNotices);
}

void noteSceneNotices(ViewerState& state) {
    if (!state.scene) return;
    std::vector<std::string> now = sceneNotices(state.settings, state.scene->lights.size(), state.scene->animations.size());
    for (std::string& n : chooseCasters(*state.scene, state.settings.casters, state.backdrops).notices)
        now.push_back(std::move(n));
    std::vector<std::string> fresh;
    for (const std::string& n : now)
        if (std::find(state.sceneNoticesShown.begin(), state.sceneNoticesShown.end(), n) == state.sceneNoticesShown.end())
            fresh.push_back(n);
    addNotices(state.status, fresh, "note: ");
    state.sceneNoticesShown = std::move(now);
}

void pickCaster(ViewerState& state, const Layout& layout, const glm::dvec2& p) {
    if (!state.scene) return;
    for (const InsetRect& v : layout.views) {
        if (!contains(v, p.x, p.y) || v.width <= 0 || v.height <= 0) continue;
        const ViewFrustum view = viewFrustum(state.settings.camera, double(v.width) / v.height);
        const glm::dmat4 toWorld = glm::inverse(view.projectionMatrix() * view.viewMatrix());
        const glm::dvec2 ndc{2.0 * (p.x - v.x) / v.width - 1.0, 1.0 - 2.0 * (p.y - v.y) / v.height};
        auto unproject = [&](double z) {
            const glm::dvec4 h = toWorld * glm::dvec4(ndc, z, 1.0);
            return glm::dvec3(h) / h.w;
        };
        const glm::dvec3 from = unproject(-1.0), to = unproject(1.0);
        const std::size_t picked = pickInstance(*state.scene, from, glm::normalize(to - from));
        const std::string done = picked == SIZE_MAX ? std::string("nothing under the cursor to switch casting of")
                                                    : toggleCasting(*state.scene, picked, state.backdrops,
                                                                    state.settings.casters);
        addNotices(state.status, {done}, "");
        return;
    }
}

void startSceneLoad(ViewerState& state, const std::string& file) {
    state.load = std::make_unique<SceneLoadJob>(file, state.loadOptions, [] { glfwPostEmptyEvent(); });
    state.uploadNext = false;
}

void openFile(ViewerState& state, const std::string& file) {
    switch (fileKindOf(file)) {
        case FileKind::Scene:
            if (state.load) {
                state.status.lastError = "still loading " + state.load->file() + "; open " + file + " afterwards";
                return;
            }
            state.loadOptions.sceneIndex = state.settings.scene.index = -1;  // another file: its default scene
            startSceneLoad(state, file);
            return;
        case FileKind::View:
        case FileKind::Screenshot:
            applyViewFile(state, file);
            return;
        case FileKind::Unknown:
            state.status.lastError = file + ": not a scene (.gltf, .glb), view state (.json) or screenshot (.png)";
            return;
    }
}

void reloadForSceneIndex(ViewerState& state) {
    if (!state.scene || state.load) return;
    const int index = state.settings.scene.index;
    // An index past the file's scenes stays unapplied (the combo offers only the file's).
    if (index < 0 || index == state.scene->shownScene || std::size_t(index) >= state.scene->sceneNames.size()) return;
    state.loadOptions.sceneIndex = index;
    startSceneLoad(state, state.scene->source);
}

void finishSceneLoad(ViewerState& state, Renderer& renderer, const SettingsOverrides& overrides) {
    const std::string file = state.load->file();
    const double parseSeconds = state.load->secondsRunning();
    LoadResult loaded = state.load->take();
    state.load.reset();
    for (const std::string& w : loaded.warnings) {
        std::cerr << "shadowlab: warning: " << w << "\n";
        // Textures that cannot be shown change the picture: said on screen too.
        if (w.find("KHR_texture_basisu") != std::string::npos) state.status.notices.push_back(w);
    }
    const bool initial = std::exchange(state.initialLoad, false);
    if (!loaded.ok()) {
        state.status.lastError = loaded.error;
        std::cerr << "shadowlab: " << loaded.error << "\n";
        // A bad scene on the command line: open the default scene instead of exiting.
        if (initial && !state.scene && file != defaultScenePath()) {
            state.initialLoad = true;
            startSceneLoad(state, defaultScenePath());
        }
        return;
    }
    state.scene = std::move(loaded.scene);
    state.sceneHash = sceneFileHash(file);
    state.controller.walkOn = nullptr;  // the eye height was measured in the old scene
    state.ground.reset();
    state.groundPlane.reset();  // the new scene has none yet; syncGroundPlane adds it if asked
    Scene& scene = *state.scene;
    if (initial) {
        applyInitialSettings(state, scene, overrides);
    } else {
        state.settings.camera = initialSettings(scene).camera;
        state.settings.animation.time = 0.0;
        state.status.lastError.clear();
    }
    // The pose at the view's time, so a loaded view shows the frame it was saved at.
    state.restPose = captureRestPose(scene);
    animateScene(scene, state.settings.animation.time, state.settings.animation.clip);
    state.posedTime = state.settings.animation.time;
    state.posedClip = state.settings.animation.clip;
    const auto uploadStart = std::chrono::steady_clock::now();
    renderer.setScene(scene, true);  // geometry now, the textures over the next frames
    state.backdrops = renderer.backdrops();
    const double uploadMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - uploadStart).count();
    std::cerr << "shadowlab: opened " << file << " (loaded in " << ui::formatNumber(parseSeconds, 3)
              << " s off the render thread, GPU upload " << ui::formatNumber(uploadMs, 3) << " ms, "
              << scene.textures.size() << " textures to follow)\n";
    state.texturesTotal = scene.textures.size();
    forgetScene(state.accuracy);
    state.status.sceneName = file;
    state.status.sceneTriangles = scene.triangleCount();
    state.animation = animationInfo(scene);
    state.controller.pivot = scene.bounds.empty() ? glm::dvec3(0.0) : scene.bounds.center();
    state.file.remember(file);
    state.sceneNoticesShown.clear();  // a new scene: its notices are new
    noteSceneNotices(state);
}

}  // namespace shadowlab::app
