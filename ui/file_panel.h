#pragma once
// File > Open (a scene, a view state or a screenshot with its settings) with a path field and the
// recent files, and the message toast: errors you cannot miss, clamping notices, load progress.
// ImGui only, never GL; the viewer does the opening.
#include "stats_panel.h"

#include <deque>
#include <string>

namespace shadowlab::ui {

struct FileUi {
    char path[1024] = "";
    std::deque<std::string> recent;  // newest first, at most kMaxRecent
    static constexpr std::size_t kMaxRecent = 8;
    // Moves `file` to the front of the recent list.
    void remember(const std::string& file);
};

// The File panel; returns the path to open, or "" when nothing was asked for.
std::string drawFilePanel(FileUi& ui);

struct LoadingInfo {
    bool active = false;
    std::string file;
    double seconds = 0.0;
    bool uploading = false;  // parsed; the GPU upload runs this frame
    double fraction = 0.0;   // the loader's progress, 0 .. 1 (or of the textures)
    bool textures = false;   // the scene shows; its textures stream in (fraction: uploaded share)
};

// A window at the top of the 3D area (x0 .. x0 + width) while there is an error, a notice or a
// load in progress. Dismissing clears the error and the notices in `status`.
void drawMessageToast(ViewerStatus& status, const LoadingInfo& loading, float x0, float width);

}  // namespace shadowlab::ui
