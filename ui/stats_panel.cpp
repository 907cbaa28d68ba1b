#include "stats_panel.h"

#include "widgets.h"

#include <imgui.h>

#include <algorithm>

namespace shadowlab::ui {

void drawStatsPanel(const FrameStats& stats, double fps, double frameCpuMs, const ViewerStatus& status,
                    const ScreenArea& area) {
    constexpr float kMinWidth = 180.0f, kMinHeight = 60.0f, kMargin = 10.0f;
    const float width = std::min(340.0f, area.x1 - area.x0 - 2.0f * kMargin), height = area.y1 - area.y0;
    if (width < kMinWidth || height < kMinHeight) return;
    // Placed every frame: below the notifications (whose height changes), above the insets' labels.
    ImGui::SetNextWindowPos(ImVec2(area.x0 + kMargin, area.y0), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, height));
    ImGui::SetNextWindowSize(ImVec2(width, 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.8f);
    if (status.collapseStats) ImGui::SetNextWindowCollapsed(true, ImGuiCond_Always);
    if (!ImGui::Begin("Stats")) {
        ImGui::End();
        return;
    }
    ImGui::TextUnformatted(status.sceneName.c_str());
    ImGui::TextDisabled("%s", status.renderer.c_str());
    ImGui::Separator();
    ImGui::Text("%.1f fps   frame CPU %.2f ms", fps, frameCpuMs);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Frames drawn per second while the picture changes (an idle window draws nothing).");
    if (!status.navigation.empty()) ImGui::TextWrapped("%s", status.navigation.c_str());
    if (ImGui::BeginTable("passes", 3, ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn("pass");
        ImGui::TableSetupColumn("CPU ms");
        ImGui::TableSetupColumn("GPU ms");
        ImGui::TableHeadersRow();
        double cpu = 0.0, gpu = 0.0;
        for (const PassStats& p : stats.passes) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(p.name.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", p.cpuMs);
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", p.gpuMs);
            cpu += p.cpuMs;
            gpu += p.gpuMs;
        }
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted("total");
        ImGui::TableNextColumn();
        ImGui::Text("%.3f", cpu);
        ImGui::TableNextColumn();
        ImGui::Text("%.3f", gpu);
        ImGui::EndTable();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "CPU: time spent issuing each pass; GPU: GL_TIME_ELAPSED timer queries, read a few frames "
            "later so the CPU never waits.");
    ImGui::Text("triangles drawn %zu (scene %zu)", stats.trianglesDrawn, status.sceneTriangles);
    ImGui::Text("draw calls %zu, instances visible %zu", stats.drawCalls, stats.instancesVisible);
    ImGui::Text("culling %.3f ms (%s)", stats.cullingCpuMs, stats.hierarchicalCulling ? "BVH" : "linear");
    if (stats.shadowMapSize > 0) {
        ImGui::Text("shadow map %d x %d: %s", stats.shadowMapSize, stats.shadowMapSize,
                    stats.shadowMapReused ? "reused" : "rendered");
        ImGui::Text("casters drawn %zu, culled %zu", stats.castersDrawn, stats.castersCulled);
        helpMarker(
            "Casters whose bounds cannot reach the intersection body B are not drawn into the shadow map "
            "(thesis 4.2, 9.2.2).");
    } else {
        ImGui::TextDisabled("no shadow map this frame");
    }
    for (const std::string& line : status.compareLines) ImGui::BulletText("%s", line.c_str());
    if (!stats.lightNote.empty()) ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "%s", stats.lightNote.c_str());
    if (!stats.shadow.fallback.empty())
        ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "%s", stats.shadow.fallback.c_str());
    ImGui::End();
}

}  // namespace shadowlab::ui
