#pragma once
// What `render` and the viewer share: loading a scene with its messages, and the settings a
// scene starts with (its first camera, then --view JSON, then --method and --set overrides).
#include "scenes/gltf_loader.h"
#include "scenes/scene.h"
#include "settings/settings.h"

#include <optional>
#include <string>
#include <string_view>
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

// What a screenshot carries beside its settings, so that `render --view shot.png` reproduces it
// without a scene or a size: the size of the 3D view the settings were rendered at, and the scene
// (the path as given to the viewer, the absolute path, and the hash of the file's bytes).
struct ShotOrigin {
    int width = 0, height = 0;  // 0: not stored (a shot saved before these were)
    std::string scene, sceneAbsolute, sceneHash;
};
inline constexpr std::string_view kViewSizePngKeyword = "shadowlab-view-size";        // "590x540"
inline constexpr std::string_view kScenePngKeyword = "shadowlab-scene";               // as given
inline constexpr std::string_view kSceneAbsolutePngKeyword = "shadowlab-scene-absolute";
inline constexpr std::string_view kSceneHashPngKeyword = "shadowlab-scene-hash";      // sceneFileHash

// "fnv1a64:" and 16 hex digits over the file's bytes (a .gltf's own JSON; its buffers and images
// are separate files and not hashed); "" when the file cannot be read.
std::string sceneFileHash(const std::string& file);
bool writeShotOrigin(const std::string& png, const ShotOrigin& origin, std::string& error);
// What `png` stores; nullopt for a PNG without a scene (or no PNG).
std::optional<ShotOrigin> readShotOrigin(const std::string& png);
// The scene file a shot names that exists (as given, else the absolute path), "" for none.
std::string shotSceneFile(const ShotOrigin& origin);
// Why the view of a shot taken in `origin`'s scene must not be applied to the open scene
// (`openScene`, whose sceneFileHash is `openHash`); "" when it is the same scene.
std::string sceneMismatch(const std::string& shot, const ShotOrigin& origin, const std::string& openScene,
                          const std::string& openHash);

}  // namespace shadowlab::app
