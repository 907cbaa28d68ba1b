#pragma once
// Small ImGui helpers shared by the panels: every parameter widget carries a tooltip (shown when
// the widget or its "(?)" marker is hovered) that says what it does and cites the paper section.
// ImGui only, never GL.
#include <imgui.h>

#include <string>

namespace shadowlab::ui {

// "(?)" after the previous widget on the same line; its tooltip is `text`.
void helpMarker(const char* text);
// Tooltip for the widget just drawn, plus a "(?)" marker after it.
void tip(const char* text);

// Double-precision widgets (the settings are doubles); `tooltip` as in tip().
bool sliderDouble(const char* label, double& value, double min, double max, const char* format, const char* tooltip,
                  ImGuiSliderFlags flags = 0);
bool dragDouble(const char* label, double& value, float speed, double min, double max, const char* format,
                const char* tooltip, ImGuiSliderFlags flags = 0);
bool checkbox(const char* label, bool& value, const char* tooltip);
bool sliderInt(const char* label, int& value, int min, int max, const char* tooltip);

// A read-out line "label  value" with its tooltip.
void readout(const char* label, const std::string& value, const char* tooltip);
std::string formatNumber(double value, int precision = 4);
// Greyed text wrapped at the window's edge (not cut off in a narrow panel).
void wrappedDisabledText(const char* text);

// Whether an ImGui window drawn last frame lies under `position` (ImGui's coordinates): asked per
// input event, at the cursor position of that event, instead of last frame's
// io.WantCaptureMouse, which still says "no" when the pointer moved onto a panel and the wheel
// turned within one frame.
bool panelAt(const ImVec2& position);

}  // namespace shadowlab::ui
