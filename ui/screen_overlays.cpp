#include "screen_overlays.h"

#include "accuracy_panel.h"

#include <imgui.h>

namespace shadowlab::ui {

void drawHeatLegendWindow(float viewWidth) {
    constexpr float kWidth = 250.0f;
    ImGui::SetNextWindowPos(ImVec2(viewWidth - kWidth - 8.0f, 8.0f), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(kWidth, 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.75f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing;
    if (ImGui::Begin("##heat legend", nullptr, flags)) {
        ImGui::TextUnformatted("screen pixels per shadow-map texel");
        drawHeatLegend();
        ImGui::TextDisabled("hover the image for the value under the cursor");
    }
    ImGui::End();
}

}  // namespace shadowlab::ui
