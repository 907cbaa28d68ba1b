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

std::vector<std::string> differingSettings(const Settings& a, const Settings& b) {
    const std::vector<std::string> ka = settingKeys(a), kb = settingKeys(b);  // the same keys, in one order
    std::vector<std::string> lines;
    for (std::size_t i = 0; i < ka.size() && i < kb.size(); ++i) {
        if (ka[i] == kb[i]) continue;
        const std::size_t eq = ka[i].find('=');
        lines.push_back(ka[i].substr(0, eq) + ": " + ka[i].substr(eq + 1) + " -> " + kb[i].substr(kb[i].find('=') + 1));
    }
    return lines;
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
    const std::vector<std::string> differences = differingSettings(settingsForA(ab, current), current);
    if (differences.empty()) {
        ImGui::TextDisabled("A and B have the same settings");
        return changed;
    }
    ImGui::TextDisabled("A and B differ in (A -> B):");
    constexpr std::size_t kShown = 6;
    for (std::size_t i = 0; i < differences.size() && i < kShown; ++i) {
        ImGui::BulletText("%s", differences[i].c_str());
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", differences[i].c_str());  // the panel may cut it
    }
    if (differences.size() > kShown) ImGui::TextDisabled("and %zu more", differences.size() - kShown);
    return changed;
}

}  // namespace shadowlab::ui
