#include "view_setup.h"

#include "frame/frame_setup.h"
#include "image/png_text.h"
#include "scenes/gltf_loader.h"
#include "settings/method_choice.h"
#include "ground_probe.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

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
    settings.camera.moveSpeed = defaultFlySpeed(scene, settings.camera.position);
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

std::string sceneFileHash(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return "";
    std::uint64_t hash = 14695981039346656037ull;  // FNV-1a 64 offset basis
    std::vector<char> buffer(1 << 16);
    while (in) {
        in.read(buffer.data(), std::streamsize(buffer.size()));
        for (std::streamsize i = 0; i < in.gcount(); ++i) {
            hash ^= std::uint8_t(buffer[std::size_t(i)]);
            hash *= 1099511628211ull;
        }
    }
    char text[32];
    std::snprintf(text, sizeof text, "fnv1a64:%016llx", static_cast<unsigned long long>(hash));
    return text;
}

bool writeShotOrigin(const std::string& png, const ShotOrigin& origin, std::string& error) {
    const std::string size = std::to_string(origin.width) + "x" + std::to_string(origin.height);
    return addPngTextToFile(png, kViewSizePngKeyword, size, error) &&
           addPngTextToFile(png, kScenePngKeyword, origin.scene, error) &&
           addPngTextToFile(png, kSceneAbsolutePngKeyword, origin.sceneAbsolute, error) &&
           addPngTextToFile(png, kSceneHashPngKeyword, origin.sceneHash, error);
}

std::optional<ShotOrigin> readShotOrigin(const std::string& png) {
    std::string error;
    const auto scene = readPngTextFromFile(png, kScenePngKeyword, error);
    if (!scene) return std::nullopt;
    ShotOrigin origin;
    origin.scene = *scene;
    origin.sceneAbsolute = readPngTextFromFile(png, kSceneAbsolutePngKeyword, error).value_or("");
    origin.sceneHash = readPngTextFromFile(png, kSceneHashPngKeyword, error).value_or("");
    const std::string size = readPngTextFromFile(png, kViewSizePngKeyword, error).value_or("");
    int w = 0, h = 0;
    char x = 0;
    std::istringstream in(size);
    if (in >> w >> x >> h && x == 'x' && w > 0 && h > 0) {
        origin.width = w;
        origin.height = h;
    }
    return origin;
}

std::string shotSceneFile(const ShotOrigin& origin) {
    std::error_code ec;
    for (const std::string& file : {origin.scene, origin.sceneAbsolute})
        if (!file.empty() && std::filesystem::is_regular_file(file, ec)) return file;
    return "";
}

std::string sceneMismatch(const std::string& shot, const ShotOrigin& origin, const std::string& openScene,
                          const std::string& openHash) {
    if (origin.sceneHash.empty() || origin.sceneHash == openHash) return "";
    return shot + " was taken in " + origin.scene + ", not in the open scene " + openScene +
           " (their contents differ): its camera would be meaningless here. Open " + origin.scene +
           " first, then the screenshot.";
}

}  // namespace shadowlab::app
