#pragma once
// The stats panel: frame rate, CPU/GPU time per pass, triangles, draw calls. ImGui only: it reads
// plain stats, never GL.
#include "frame_stats.h"

#include <string>

namespace shadowlab::ui {

struct ViewerStatus {
    std::string sceneName;
    std::size_t sceneTriangles = 0;
    std::string renderer;    // GL_RENDERER
    std::string lastError;   // e.g. a dropped file that failed to load
    std::string lastMessage;  // e.g. "saved screenshot ..."
};

void drawStatsPanel(const FrameStats& stats, double fps, double frameCpuMs, const ViewerStatus& status);

}  // namespace shadowlab::ui
