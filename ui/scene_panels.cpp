// The scene's light and camera panels: which light casts (the file's, the viewer's sun or spot),
// and the camera presets of the file. Split from panels.cpp; the same settings contract.
#include "panels.h"

#include "frame/frame_setup.h"
#include "settings/method_choice.h"
#include "widgets.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace shadowlab::ui {

bool drawLightPanel(Settings& s, const Scene& scene) {
    bool changed = false;
    LightSettings& l = s.light;
    // One list: the glTF lights, then the two lights set by angles.
    std::string current;
    if (l.source == LightSource::Sun)
        current = "Sun (azimuth / elevation)";
    else if (l.source == LightSource::Spot)
        current = "Spot (position, azimuth / elevation)";
    else if (l.sceneLight < int(scene.lights.size()))
        current = "glTF: " + scene.lights[std::size_t(l.sceneLight)].name;
    else
        current = "glTF light " + std::to_string(l.sceneLight) + " (missing)";
    if (ImGui::BeginCombo("light", current.c_str())) {
        for (std::size_t i = 0; i < scene.lights.size(); ++i) {
            const Light& light = scene.lights[i];
            const char* kind = light.type == LightType::Directional ? "directional"
                               : light.type == LightType::Spot      ? "spot"
                                                                    : "point, no shadow";
            const std::string name = "glTF: " + (light.name.empty() ? "light " + std::to_string(i) : light.name) +
                                     " (" + kind + ")##" + std::to_string(i);
            const bool selected = l.source == LightSource::Scene && l.sceneLight == int(i);
            if (ImGui::Selectable(name.c_str(), selected)) {
                changed |= !selected;
                l.source = LightSource::Scene;
                l.sceneLight = int(i);
            }
        }
        if (ImGui::Selectable("Sun (azimuth / elevation)", l.source == LightSource::Sun)) {
            changed |= l.source != LightSource::Sun;
            l.source = LightSource::Sun;
        }
        if (ImGui::Selectable("Spot (position, azimuth / elevation)", l.source == LightSource::Spot)) {
            changed |= l.source != LightSource::Spot;
            l.source = LightSource::Spot;
        }
        ImGui::EndCombo();
    }
    tip("The shadow-casting light: one of the scene's KHR_lights_punctual lights (point lights are lit without "
        "shadows), a directional sun or a spot light. Directional vs. point lights change what PSM sees after the "
        "projection (Stamminger & Drettakis 3).");
    const bool angles = l.source != LightSource::Scene;
    ImGui::BeginDisabled(!angles);
    changed |= sliderDouble("azimuth", l.azimuthDeg, -180.0, 180.0, "%.1f deg",
                            "Compass direction the light comes from, around +Y (0 = from +X). Turning it changes the "
                            "angle gamma between view and light (thesis 8.3, Figs. 8.10, 8.11).");
    changed |= sliderDouble("elevation", l.elevationDeg, -10.0, 90.0, "%.1f deg",
                            "Height of the light above the horizon. Low suns give long shadows, the hard case for "
                            "uniform maps (thesis 3.1).");
    ImGui::EndDisabled();
    if (l.source == LightSource::Spot) {
        glm::vec3 p(l.spotPosition);
        if (ImGui::DragFloat3("spot position", &p.x, 0.1f)) {
            l.spotPosition = glm::dvec3(p);
            changed = true;
        }
        tip("Where the spot light stands (world units). Spot lights add their frustum L to B (thesis eq. 4.2).");
        changed |= sliderDouble("cone", l.spotOuterConeDeg, 1.0, 89.0, "%.1f deg",
                                "Outer cone half-angle; the light frustum L circumscribes it (thesis 9.2.2).");
        changed |=
            dragDouble("range", l.spotRange, 0.1f, 0.0, 1e6, "%.1f",
                       "Far distance of the spot frustum L; 0 = up to the scene bounds (thesis eq. 4.2, 9.2.2).");
    }
    glm::vec3 color(l.color);
    if (ImGui::ColorEdit3("colour", &color.x)) {
        l.color = glm::dvec3(color);
        changed = true;
    }
    tip("Light colour (linear). Diffuse lighting fades light towards grazing angles, which hides projection aliasing "
        "(thesis 6.2, 9.4.1).");
    changed |= sliderDouble("intensity", l.intensity, 0.0, 20.0, "%.2f",
                            "Light brightness (relative radiance); the lit-vs-ambient contrast decides how visible "
                            "shadow aliasing is (thesis 6.2, 9.4.1).");
    changed |= sliderDouble("ambient", l.ambient, 0.0, 1.0, "%.2f",
                            "Global ambient term, never shadowed. Keep it low: a strong ambient term reveals "
                            "projection aliasing that diffuse lighting hides (thesis 6.2, 9.4.1).");
    ImGui::BeginDisabled(l.source != LightSource::Sun);
    changed |= checkbox("animate sun", l.animateSun,
                        "Turn the sun around the scene with the scene clock (Animation panel), to see the methods "
                        "cope with every light angle, including light behind the viewer (thesis 7.2.2, 8.3).");
    changed |= sliderDouble("sun speed", l.sunDegreesPerSecond, -90.0, 90.0, "%.1f deg/s",
                            "Degrees of azimuth per second of scene time. A moving light forces the shadow map to be "
                            "regenerated every frame (Scherzer, robust shadow maps 1.1: dynamic environments).");
    ImGui::EndDisabled();
    return changed;
}

bool drawCameraPanel(Settings& s, const Scene& scene) {
    bool changed = false;
    CameraSettings& c = s.camera;
    changed |= sliderDouble("fov y", c.fovYDeg, 5.0, 150.0, "%.1f deg",
                            "Vertical field of view. Wide angles make perspective aliasing worse (thesis 3.1, 8.2.1).");
    const double farLimit = std::max(c.farPlane * 10.0, 1e4);
    if (sliderDouble("near", c.nearPlane, 1e-4, std::max(1e-3, c.farPlane * 0.5), "%.4g",
                     "Camera near plane z_n. It enters n_opt = z_n + sqrt(z_n z_f) (thesis eq. 9.1, 9.2.5): a "
                     "smaller z_n warps more. Log scale.",
                     ImGuiSliderFlags_Logarithmic)) {
        changed = true;
        c.farPlane = std::max(c.farPlane, c.nearPlane * 1.01);
    }
    if (sliderDouble("far", c.farPlane, std::max(c.nearPlane * 1.01, 1e-3), farLimit, "%.4g",
                     "Camera far plane z_f: bounds V and hence B (thesis 4.2, 9.2.5). Log scale.",
                     ImGuiSliderFlags_Logarithmic)) {
        changed = true;
    }
    changed |= sliderDouble("speed", c.moveSpeed, 0.05, 1000.0, "%.3g m/s",
                            "Fly speed for W/A/S/D/Q/E (shift: 4x). Left drag looks, right drag orbits, wheel dollies.",
                            ImGuiSliderFlags_Logarithmic);
    ImGui::TextDisabled("pos (%.2f, %.2f, %.2f)  yaw %.1f  pitch %.1f", c.position.x, c.position.y, c.position.z,
                        c.yawDeg, c.pitchDeg);
    if (!scene.cameras.empty()) {
        ImGui::TextUnformatted("presets (glTF cameras):");
        ImGui::SameLine();
        helpMarker("Jump to a camera of the glTF file (its position, direction, fov, near and far; roll is dropped).");
        std::vector<std::string> names;
        for (std::size_t i = 0; i < scene.cameras.size(); ++i)
            names.push_back(scene.cameras[i].name.empty() ? "camera " + std::to_string(i) : scene.cameras[i].name);
        const ImGuiStyle& style = ImGui::GetStyle();
        const std::vector<FlowItem> flow =
            flowLayout(names, ImGui::GetContentRegionAvail().x, 2.0f * style.FramePadding.x, style.ItemSpacing.x,
                       [](const std::string& t) { return ImGui::CalcTextSize(t.c_str()).x; });
        for (std::size_t i = 0; i < flow.size(); ++i) {
            if (i > 0 && flow[i].row == flow[i - 1].row) ImGui::SameLine();
            const std::string label = flow[i].shown + "##cam" + std::to_string(i);
            if (ImGui::Button(label.c_str(), ImVec2(flow[i].width, 0))) {
                c = cameraFromScene(scene.cameras[i], c);
                changed = true;
            }
            if (flow[i].shown != names[i] && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", names[i].c_str());
        }
    }
    if (scene.sceneNames.size() > 1) {
        auto name = [&](int i) {
            const std::string& n = scene.sceneNames[std::size_t(i)];
            return "scene " + std::to_string(i) + (n.empty() ? "" : " " + n);
        };
        if (ImGui::BeginCombo("glTF scene", name(std::max(scene.shownScene, 0)).c_str())) {
            for (int i = 0; i < int(scene.sceneNames.size()); ++i)
                if (ImGui::Selectable(name(i).c_str(), i == scene.shownScene)) {
                    s.scene.index = i;  // the viewer reloads the file with this scene (scene.index)
                    changed = true;
                }
            ImGui::EndCombo();
        }
        tip("The file holds several scenes (glTF 2.0 3.5); the default one opens. Choosing another reloads the file.");
    }
    return changed;
}

}  // namespace shadowlab::ui
