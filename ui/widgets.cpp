#include "widgets.h"

#include <imgui_internal.h>

#include <cmath>
#include <cstdio>

namespace shadowlab::ui {

namespace {

void tooltipText(const char* text) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    ImGui::TextUnformatted(text);
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

}  // namespace

void helpMarker(const char* text) {
    ImGui::SameLine();
    ImGui::TextDisabled("(?)");
    // Disabled controls explain themselves too (why they are disabled is often the point).
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) tooltipText(text);
}

void tip(const char* text) {
    if (!text || !*text) return;
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) tooltipText(text);
    helpMarker(text);
}

bool sliderDouble(const char* label, double& value, double min, double max, const char* format, const char* tooltip,
                  ImGuiSliderFlags flags) {
    const bool changed = ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &min, &max, format, flags);
    tip(tooltip);
    return changed;
}

bool dragDouble(const char* label, double& value, float speed, double min, double max, const char* format,
                const char* tooltip, ImGuiSliderFlags flags) {
    const bool changed = ImGui::DragScalar(label, ImGuiDataType_Double, &value, speed, &min, &max, format, flags);
    tip(tooltip);
    return changed;
}

bool checkbox(const char* label, bool& value, const char* tooltip) {
    const bool changed = ImGui::Checkbox(label, &value);
    tip(tooltip);
    return changed;
}

bool sliderInt(const char* label, int& value, int min, int max, const char* tooltip) {
    const bool changed = ImGui::SliderInt(label, &value, min, max, "%d", ImGuiSliderFlags_AlwaysClamp);
    tip(tooltip);
    return changed;
}

void readout(const char* label, const std::string& value, const char* tooltip) {
    ImGui::TextUnformatted(label);
    ImGui::SameLine(ImGui::GetFontSize() * 11.0f);
    ImGui::TextUnformatted(value.c_str());
    if (ImGui::IsItemHovered() && tooltip) tooltipText(tooltip);
    if (tooltip) helpMarker(tooltip);
}

void wrappedDisabledText(const char* text) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", text);
    ImGui::PopStyleColor();
}

std::string formatNumber(double value, int precision) {
    if (!std::isfinite(value)) return std::isnan(value) ? "n/a" : (value > 0 ? "+inf" : "-inf");
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", precision, value);
    return buf;
}

bool panelAt(const ImVec2& position) {
    const ImGuiContext* context = ImGui::GetCurrentContext();
    if (!context) return false;
    for (const ImGuiWindow* window : context->Windows) {
        if (!window->Active || window->Hidden || (window->Flags & ImGuiWindowFlags_NoMouseInputs)) continue;
        // The resize grips reach a few pixels beyond the window (ImGui's WINDOWS_HOVER_PADDING).
        const float pad = (window->Flags & ImGuiWindowFlags_NoResize) ? 0.0f : 4.0f;
        ImRect rect = window->Rect();
        rect.Expand(pad);
        if (rect.Contains(position)) return true;
    }
    return false;
}

}  // namespace shadowlab::ui
