#include "file_panel.h"

#include "widgets.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace shadowlab::ui {

void FileUi::remember(const std::string& file) {
    recent.erase(std::remove(recent.begin(), recent.end(), file), recent.end());
    recent.push_front(file);
    while (recent.size() > kMaxRecent) recent.pop_back();
}

std::string drawFilePanel(FileUi& ui) {
    std::string open;
    const bool entered =
        ImGui::InputText("path##open", ui.path, sizeof ui.path, ImGuiInputTextFlags_EnterReturnsTrue);
    tip("A scene (.gltf, .glb), a view state (.json) or a screenshot saved by shadowlab (.png, its settings are "
        "embedded). A scene that fails to load leaves the current one on screen. Dropping a file on the window "
        "does the same.");
    ImGui::SameLine();
    if ((ImGui::Button("open") || entered) && ui.path[0] != '\0') open = ui.path;
    if (!ui.recent.empty()) {
        ImGui::TextDisabled("recent:");
        for (std::size_t i = 0; i < ui.recent.size(); ++i) {
            const std::string& f = ui.recent[i];
            const std::string label = f + "##recent" + std::to_string(i);
            if (ImGui::Selectable(label.c_str())) open = f;
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", f.c_str());
        }
    }
    return open;
}

void drawMessageToast(ViewerStatus& status, const LoadingInfo& loading, float x0, float width) {
    if (status.lastError.empty() && status.notices.empty() && !loading.active) return;
    const float toastWidth = std::min(width - 20.0f, 560.0f);
    ImGui::SetNextWindowPos(ImVec2(x0 + 0.5f * (width - toastWidth), 8.0f), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(toastWidth, 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.92f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing;
    if (!ImGui::Begin("##messages", nullptr, flags)) {
        ImGui::End();
        return;
    }
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
    if (!status.lastError.empty() || !status.notices.empty()) {
        if (ImGui::SmallButton("dismiss")) {
            status.lastError.clear();
            status.notices.clear();
        }
    }
    ImGui::End();
}

}  // namespace shadowlab::ui
