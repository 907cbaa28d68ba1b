#pragma once
// Opening files in the viewer: one path for File > Open, drop, "load view" and the command line,
// by the file's kind (scene_loading.h's fileKindOf); scenes load on a worker thread and replace the
// current scene only when they loaded, view states apply as a whole or not at all.
#include "renderer.h"
#include "view_setup.h"
#include "viewer/viewer_state.h"

#include <string>
#include <vector>

namespace shadowlab::app {

// Starts loading `file` on a worker thread (with state.loadOptions).
void startSceneLoad(ViewerState& state, const std::string& file);

// A scene, a view state or a screenshot with its settings; anything else is an error in the toast.
void openFile(ViewerState& state, const std::string& file);

// A finished load: the new scene replaces the current one, or the error is shown and the current
// scene stays. The command line's scene takes `overrides`.
void finishSceneLoad(ViewerState& state, Renderer& renderer, const SettingsOverrides& overrides);
// settings.scene.index (the glTF scene combo) differs from the scene shown: the file reloads with it.
void reloadForSceneIndex(ViewerState& state);

// The settings' notices about the scene (sceneNotices: a light.sceneLight beyond its lights,
// light.animateSun under a scene light) into the toast, each once when it becomes true.
void noteSceneNotices(ViewerState& state);
// Ctrl+click in a view at framebuffer point `p` (top-left origin): the object under it switches
// its casting (frame/caster_model.h: toggleCasting), with a notice saying which and how.
void pickCaster(ViewerState& state, const Layout& layout, const glm::dvec2& p);

// Clamping notices ("shadowMapSize 12345 -> 8192") into the toast and on stderr; `prefix` starts
// each line ("adjusted " for sanitize's changes, "" for lines that are whole sentences).
void addNotices(ui::ViewerStatus& status, const std::vector<std::string>& changes,
                const std::string& prefix = "adjusted ");

}  // namespace shadowlab::app
