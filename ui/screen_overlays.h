#pragma once
// Windows drawn over the 3D image itself (not the control panels): the heat-map legend of the
// aliasing error view. ImGui only.
namespace shadowlab::ui {

// The colour bar of the aliasing heat map at the top-right of the 3D area (0 .. viewWidth), its
// top at `top` (below the notification area).
void drawHeatLegendWindow(float viewWidth, float top);

}  // namespace shadowlab::ui
