#pragma once
// What `render` and the viewer share: loading a scene with its messages, and the settings a
// scene starts with (its first camera, then --view JSON, then --method and --set overrides).
#include "scenes/gltf_loader.h"
#include "scenes/scene.h"
#include "settings/settings.h"

#include <optional>
#include <string>
#include <vector>

namespace shadowlab::app {

std::string defaultScenePath();

// Loads SCENE; on failure prints "shadowlab: <file>: <reason>" and returns nullopt.
std::optional<Scene> loadSceneReporting(const std::string& file, const LoadOptions& options = {});

// Settings for the first view of a scene: the first glTF camera (or the framing camera).
Settings initialSettings(const Scene& scene);

// The scene camera NAME, or INDEX (0-based) when the text is a number, into settings.camera.
bool applySceneCamera(const Scene& scene, const std::string& nameOrIndex, Settings& settings, std::string& error);
bool applySceneCamera(const Scene& scene, int index, Settings& settings, std::string& error);

struct SettingsOverrides {
    std::string viewFile;              // --view VIEW.json
    std::string method;                // --method
    std::vector<std::string> sets;     // --set key=value
};
// Applies the overrides in that order; false with `error` on a bad file/key/value.
bool applyOverrides(Settings& settings, const SettingsOverrides& overrides, std::string& error);
// The glTF scene the overrides ask for (scene.index), into `load` before the file is read.
bool requestedScene(const SettingsOverrides& overrides, LoadOptions& load, std::string& error);

bool readTextFile(const std::string& file, std::string& text, std::string& error);

// Applies a view state to `settings` (all of it or, on error, nothing): a JSON file, or a PNG
// screenshot shadowlab saved, whose settings JSON sits in a tEXt chunk (renderer/image/png_text.h).
bool readViewFile(const std::string& file, Settings& settings, std::string& error);

}  // namespace shadowlab::app
