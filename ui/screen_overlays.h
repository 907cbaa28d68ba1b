#pragma once
// Windows drawn over the 3D image itself (not the control panels): the heat-map legend of the
// aliasing error view. ImGui only.
namespace shadowlab::ui {

// The colour bar of the aliasing heat map at the top-right of the 3D area (0 .. viewWidth).
void drawHeatLegendWindow(float viewWidth);

}  // namespace shadowlab::ui
