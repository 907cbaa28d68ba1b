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
    std::string lastMessage;                // e.g. "saved screenshot ...": fades after a few seconds
    std::string messageShown;               // the message whose clock runs (ui/notifications.h)
    double messageSince = 0.0;              // when it first showed, seconds
    std::vector<std::string> notices;       // e.g. "shadowMapSize 12345 -> 8192" (clamped values)
    bool collapseStats = false;             // fold the stats window this frame (split compare began)
    std::vector<std::string> compareLines;  // one per split-compare view
    std::string navigation;                 // fly / walk speed and the keys that change it
};

// Where a window over the 3D area may go: below the notification area, above the insets.
struct ScreenArea {
    float x0 = 0.0f, y0 = 0.0f, x1 = 0.0f, y1 = 0.0f;
};

// The Stats window, kept inside `area` (its top-left corner, at most its height; left out when the
// area is too small to hold its first lines). `fps`: frames per second of the drawing itself.
void drawStatsPanel(const FrameStats& stats, double fps, double frameCpuMs, const ViewerStatus& status,
                    const ScreenArea& area);

}  // namespace shadowlab::ui
