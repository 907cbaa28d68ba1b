#include "stats_panel.h"

#include <imgui.h>

namespace shadowlab::ui {

void drawStatsPanel(const FrameStats& stats, double fps, double frameCpuMs, const ViewerStatus& status) {
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(330, 0), ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Stats")) {
        ImGui::End();
        return;
    }
    ImGui::Text("%s", status.sceneName.c_str());
    ImGui::TextDisabled("%s", status.renderer.c_str());
    ImGui::Separator();
    ImGui::Text("%.1f fps   frame CPU %.2f ms", fps, frameCpuMs);
    if (ImGui::BeginTable("passes", 3, ImGuiTableFlags_SizingStretchProp)) {
        ImGui::TableSetupColumn("pass");
        ImGui::TableSetupColumn("CPU ms");
        ImGui::TableSetupColumn("GPU ms");
        ImGui::TableHeadersRow();
        for (const PassStats& p : stats.passes) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(p.name.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", p.cpuMs);
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", p.gpuMs);
        }
        ImGui::EndTable();
    }
    ImGui::Text("triangles drawn %zu (scene %zu)", stats.trianglesDrawn, status.sceneTriangles);
    ImGui::Text("draw calls %zu", stats.drawCalls);
    if (stats.shadowMapSize > 0) {
        ImGui::Text("shadow map %d x %d", stats.shadowMapSize, stats.shadowMapSize);
        ImGui::Text("casters drawn %zu, culled %zu", stats.castersDrawn, stats.castersCulled);
    }
    if (!stats.lightNote.empty()) ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "%s", stats.lightNote.c_str());
    if (!status.lastError.empty()) ImGui::TextColored(ImVec4(1, 0.35f, 0.3f, 1), "%s", status.lastError.c_str());
    if (!status.lastMessage.empty()) ImGui::TextWrapped("%s", status.lastMessage.c_str());
    ImGui::End();
}

}  // namespace shadowlab::ui
