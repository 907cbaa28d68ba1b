#include "ab_panel.h"

#include "widgets.h"

#include <imgui.h>

namespace shadowlab::ui {

Settings settingsForA(const AbCompare& ab, const Settings& current) {
    Settings a = ab.a ? *ab.a : current;
    if (ab.sameCamera) a.camera = current.camera;
    a.compare.count = 1;  // one view each
    return a;
}

bool drawAbPanel(AbCompare& ab, const Settings& current) {
    bool changed = false;
    if (ImGui::Button("store as A")) {
        ab.a = current;
        ab.active = true;
        changed = true;
    }
    tip("Keep the current settings (every parameter) as A. Then change anything: the current settings are B.");
    ImGui::SameLine();
    ImGui::BeginDisabled(!ab.a);
    changed |= ImGui::Checkbox("show A/B", &ab.active);
    ImGui::EndDisabled();
    if (!ab.a) {
        ImGui::TextDisabled("(store A first)");
        return changed;
    }
    int mode = int(ab.mode);
    changed |= ImGui::RadioButton("A | B", &mode, int(AbMode::SideBySide));
    ImGui::SameLine();
    changed |= ImGui::RadioButton("wipe", &mode, int(AbMode::Wipe));
    ImGui::SameLine();
    changed |= ImGui::RadioButton("difference", &mode, int(AbMode::Difference));
    ab.mode = AbMode(mode);
    if (ab.mode == AbMode::Wipe)
        changed |= sliderDouble("wipe", ab.wipe, 0.0, 1.0, "%.2f", "Left of the line: A; right of it: B.");
    if (ab.mode == AbMode::Difference) {
        changed |= sliderDouble("difference gain", ab.diffScale, 1.0, 64.0, "x%.0f",
                                "|A - B| per channel, multiplied by this. Black: identical pixels.",
                                ImGuiSliderFlags_Logarithmic);
        if (!ab.lastDifference.empty()) ImGui::TextDisabled("%s", ab.lastDifference.c_str());
    }
    changed |= checkbox("same camera", ab.sameCamera,
                        "Render A with the current camera, so moving around compares the same view. Off: A keeps the "
                        "camera it was stored with.");
    const bool differs = !(settingsForA(ab, current) == current);
    ImGui::TextDisabled(differs ? "A and B differ in their settings" : "A and B have the same settings");
    return changed;
}

}  // namespace shadowlab::ui
