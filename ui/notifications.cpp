#include "notifications.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cstdio>

namespace shadowlab::ui {

namespace {
constexpr float kTop = 8.0f;
constexpr float kGap = 6.0f;  // between the area and the windows below it
}  // namespace

bool notificationsFading(const ViewerStatus& status) { return !status.lastMessage.empty(); }

float drawNotifications(ViewerStatus& status, const LoadingInfo& loading, float x0, float width, double now) {
    if (status.lastMessage != status.messageShown) {  // a new info message: its clock starts
        status.messageShown = status.lastMessage;
        status.messageSince = now;
    }
    const double age = now - status.messageSince;
    if (!status.lastMessage.empty() && age > kInfoSeconds + kInfoFadeSeconds) status.lastMessage.clear();
    const bool info = !status.lastMessage.empty();
    if (status.lastError.empty() && status.notices.empty() && !loading.active && !info) return kTop;

    const float areaWidth = std::max(40.0f, std::min(width - 20.0f, 560.0f));
    ImGui::SetNextWindowPos(ImVec2(x0 + 0.5f * (width - areaWidth), kTop), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(areaWidth, 0.0f), ImGuiCond_Always);
    const bool persistent = !status.lastError.empty() || !status.notices.empty() || loading.active;
    // Only an info message alone fades: an error beside it keeps the window.
    const float fade = persistent ? 1.0f : float(std::clamp(1.0 - (age - kInfoSeconds) / kInfoFadeSeconds, 0.0, 1.0));
    ImGui::SetNextWindowBgAlpha(0.92f * fade);
    ImGui::PushStyleVar(ImGuiStyleVar_Alpha, std::max(fade, 0.05f));
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing;
    float bottom = kTop;
    if (ImGui::Begin("##notifications", nullptr, flags)) {
        // In front of the Stats window and the panels, without taking the keyboard focus.
        ImGui::BringWindowToDisplayFront(ImGui::GetCurrentWindow());
        if (loading.active) {
            if (loading.textures)
                ImGui::Text("uploading the textures of %s", loading.file.c_str());
            else
                ImGui::Text("%s %s  (%.1f s)", loading.uploading ? "uploading" : "loading", loading.file.c_str(),
                            loading.seconds);
            const float fraction =
                loading.uploading && !loading.textures ? 1.0f : float(std::clamp(loading.fraction, 0.0, 1.0));
            char label[32];
            std::snprintf(label, sizeof label, "%.0f %%", 100.0 * fraction);
            ImGui::ProgressBar(fraction, ImVec2(-1.0f, 0.0f), label);
        }
        if (!status.lastError.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
            ImGui::TextWrapped("%s", status.lastError.c_str());
            ImGui::PopStyleColor();
        }
        for (const std::string& n : status.notices) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "%s", n.c_str());
        if (info) ImGui::TextWrapped("%s", status.lastMessage.c_str());
        if ((!status.lastError.empty() || !status.notices.empty()) && ImGui::SmallButton("dismiss")) {
            status.lastError.clear();
            status.notices.clear();
        }
        bottom = ImGui::GetWindowPos().y + ImGui::GetWindowSize().y;
    }
    ImGui::End();
    ImGui::PopStyleVar();
    return bottom + kGap;
}

}  // namespace shadowlab::ui
