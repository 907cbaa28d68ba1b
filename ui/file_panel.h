#pragma once
// File > Open (a scene, a view state or a screenshot with its settings) with a path field and the
// recent files. ImGui only, never GL; the viewer does the opening.
#include "stats_panel.h"

#include <deque>
#include <string>
#include <vector>

namespace shadowlab::ui {

struct FileUi {
    char path[1024] = "";
    bool browsing = false;   // the browser under the path field is open
    std::string browseDir;   // the folder it lists ("" = the working directory)
    std::deque<std::string> recent;  // newest first, at most kMaxRecent
    static constexpr std::size_t kMaxRecent = 8;
    // Moves `file` to the front of the recent list.
    void remember(const std::string& file);
};

// One line of the file browser: a folder (opened by a click) or a file the viewer opens.
struct BrowseEntry {
    std::string name;
    bool folder = false;
};
// The sub-folders (hidden ones left out) and the scenes, view states and screenshots (.gltf,
// .glb, .json, .png) in `dir`, folders first, each group by name; empty when `dir` cannot be read.
std::vector<BrowseEntry> browseEntries(const std::string& dir);

// The File panel; returns the path to open, or "" when nothing was asked for.
std::string drawFilePanel(FileUi& ui);

}  // namespace shadowlab::ui
