#include "screen_overlays.h"

#include "accuracy_panel.h"
#include "widgets.h"

#include <imgui.h>

namespace shadowlab::ui {

void drawHeatLegendWindow(float viewWidth, float top) {
    constexpr float kWidth = 250.0f;
    ImGui::SetNextWindowPos(ImVec2(viewWidth - kWidth - 8.0f, top), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(kWidth, 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.75f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing;
    if (ImGui::Begin("##heat legend", nullptr, flags)) {
        ImGui::TextUnformatted("screen pixels per shadow-map texel");
        drawHeatLegend();
        wrappedDisabledText("hover the image for the value under the cursor");
    }
    ImGui::End();
}

}  // namespace shadowlab::ui
