#include "view_setup.h"

#include "frame/frame_setup.h"
#include "image/png_text.h"
#include "scenes/gltf_loader.h"
#include "settings/method_choice.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace shadowlab::app {

std::string defaultScenePath() { return SHADOWLAB_DEFAULT_SCENE; }

std::optional<Scene> loadSceneReporting(const std::string& file, const LoadOptions& options) {
    LoadResult result = loadScene(file, options);
    for (const std::string& w : result.warnings) std::cerr << "shadowlab: warning: " << w << "\n";
    if (!result.ok()) {
        std::cerr << "shadowlab: " << result.error << "\n";
        return std::nullopt;
    }
    return std::move(result.scene);
}

Settings initialSettings(const Scene& scene) {
    Settings settings;
    if (!scene.cameras.empty()) settings.camera = cameraFromScene(scene.cameras.front(), settings.camera);
    const double size = glm::length(scene.bounds.extent());
    if (std::isfinite(size) && size > 0.0) settings.camera.moveSpeed = std::max(0.5, size * 0.1);
    return settings;
}

bool applySceneCamera(const Scene& scene, int index, Settings& settings, std::string& error) {
    if (index < 0 || std::size_t(index) >= scene.cameras.size()) {
        error = "camera index " + std::to_string(index) + " but the scene has " + std::to_string(scene.cameras.size()) +
                " camera(s)";
        return false;
    }
    settings.camera = cameraFromScene(scene.cameras[std::size_t(index)], settings.camera);
    return true;
}

bool applySceneCamera(const Scene& scene, const std::string& nameOrIndex, Settings& settings, std::string& error) {
    for (std::size_t i = 0; i < scene.cameras.size(); ++i)
        if (scene.cameras[i].name == nameOrIndex) return applySceneCamera(scene, int(i), settings, error);
    const bool digits = !nameOrIndex.empty() && nameOrIndex.size() < 10 &&
                        nameOrIndex.find_first_not_of("0123456789") == std::string::npos;
    if (digits) return applySceneCamera(scene, std::stoi(nameOrIndex), settings, error);
    std::string names;
    for (const auto& c : scene.cameras) names += (names.empty() ? "" : ", ") + (c.name.empty() ? "(unnamed)" : c.name);
    error = "no camera named '" + nameOrIndex.substr(0, 80) + "' in the scene (cameras: " +
            (names.empty() ? "none" : names.substr(0, 400)) + ")";
    return false;
}

bool readTextFile(const std::string& file, std::string& text, std::string& error) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        error = "cannot open '" + file + "'";
        return false;
    }
    std::ostringstream s;
    s << in.rdbuf();
    text = s.str();
    return true;
}

bool readViewFile(const std::string& file, Settings& settings, std::string& error) {
    // A FIFO would block the probe below and a device never end; a huge text is refused unread.
    std::error_code ec;
    const auto status = std::filesystem::status(file, ec);
    if (!ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
        error = file + ": not a regular file (a view is a .json file or a .png with settings)";
        return false;
    }
    std::string text;
    char head[8] = {};
    std::ifstream probe(file, std::ios::binary);
    probe.read(head, sizeof head);
    if (probe.gcount() == 8 && std::string(head, 8) == "\x89PNG\r\n\x1a\n") {
        std::optional<std::string> embedded = readPngTextFromFile(file, kSettingsPngKeyword, error);
        if (!embedded) return false;
        text = std::move(*embedded);
    } else if (probe.gcount() >= 4 && std::string(head, 4) == "glTF") {
        error = file + ": a glTF scene, not a view state (open it as a scene)";
        return false;
    } else if (const auto size = std::filesystem::file_size(file, ec); !ec && size > kMaxSettingsJsonBytes) {
        error = file + ": " + std::to_string(size) + " bytes; a view file is at most " +
                std::to_string(kMaxSettingsJsonBytes) + " bytes";
        return false;
    } else if (!readTextFile(file, text, error)) {
        return false;
    }
    Settings loaded = settings;
    if (!fromJsonText(text, loaded, error)) {
        error = file + ": " + error;
        return false;
    }
    settings = loaded;
    return true;
}

bool requestedScene(const SettingsOverrides& overrides, LoadOptions& load, std::string& error) {
    Settings settings;
    if (!applyOverrides(settings, overrides, error)) return false;
    load.sceneIndex = settings.scene.index;
    return true;
}

bool applyOverrides(Settings& settings, const SettingsOverrides& overrides, std::string& error) {
    if (!overrides.viewFile.empty() && !readViewFile(overrides.viewFile, settings, error)) return false;
    // One map or cascades (settings/method_choice.h); "all" is render's side by side.
    if (!overrides.method.empty() && overrides.method != "all") {
        MethodChoice choice;
        if (!parseMethodChoice(overrides.method, choice)) {
            error = "unknown method '" + overrides.method + "' (" + methodChoiceNames() + ", all)";
            return false;
        }
        applyMethodChoice(settings, choice);
    }
    for (const std::string& s : overrides.sets)
        if (!setByKey(settings, s, error)) return false;
    for (const std::string& change : sanitize(settings)) std::cerr << "shadowlab: adjusted " << change << "\n";
    return true;
}

}  // namespace shadowlab::app
