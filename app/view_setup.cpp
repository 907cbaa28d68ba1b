#include "view_setup.h"

#include "frame_setup.h"
#include "scenes/gltf_loader.h"

#include <fstream>
#include <iostream>
#include <sstream>

namespace shadowlab::app {

std::string defaultScenePath() { return SHADOWLAB_DEFAULT_SCENE; }

std::optional<Scene> loadSceneReporting(const std::string& file) {
    LoadResult result = loadScene(file);
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

bool applyOverrides(Settings& settings, const SettingsOverrides& overrides, std::string& error) {
    if (!overrides.viewFile.empty()) {
        std::string text;
        if (!readTextFile(overrides.viewFile, text, error)) return false;
        if (!fromJsonText(text, settings, error)) {
            error = overrides.viewFile + ": " + error;
            return false;
        }
    }
    if (!overrides.method.empty() && overrides.method != "all") {
        ShadowMethod m{};
        if (!parseMethod(overrides.method, m)) {
            error = "unknown method '" + overrides.method + "' (ssm, ssm-unfocused, psm, lispsm, all)";
            return false;
        }
        settings.method = m;
    }
    for (const std::string& s : overrides.sets)
        if (!setByKey(settings, s, error)) return false;
    for (const std::string& change : sanitize(settings)) std::cerr << "shadowlab: adjusted " << change << "\n";
    return true;
}

}  // namespace shadowlab::app
