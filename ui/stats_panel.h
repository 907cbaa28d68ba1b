#pragma once
// The stats panel: frame rate, CPU/GPU time per pass (GL timer queries, read a few frames late),
// casters drawn/culled, triangles, shadow map size. ImGui only: it reads plain stats, never GL.
#include "frame/frame_stats.h"

#include <string>
#include <vector>

namespace shadowlab::ui {

struct ViewerStatus {
    std::string sceneName;
    std::size_t sceneTriangles = 0;
    std::string renderer;                   // GL_RENDERER
    std::string lastError;                  // e.g. a dropped file that failed to load
    std::string lastMessage;                // e.g. "saved screenshot ..."
    std::vector<std::string> notices;       // e.g. "shadowMapSize 12345 -> 8192" (clamped values)
    bool collapseStats = false;             // fold the stats window this frame (split compare began)
    std::vector<std::string> compareLines;  // one per split-compare view
    std::string navigation;                 // fly / walk speed and the keys that change it
};

void drawStatsPanel(const FrameStats& stats, double fps, double frameCpuMs, const ViewerStatus& status);

}  // namespace shadowlab::ui
