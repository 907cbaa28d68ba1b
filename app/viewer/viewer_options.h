#pragma once
// What `shadowlab [SCENE] [options]` hands the interactive viewer (the command line's options are
// declared in command_line.cpp, the only viewer file that compiles all of CLI11).
#include "view_setup.h"

#include <string>
#include <vector>

namespace shadowlab::app {

struct ViewerOptions {
    std::string scene;
    int frames = 0;          // 0 = run until closed
    std::string screenshot;  // written after the last frame
    std::string saveView;    // view state JSON written on exit
    bool noUi = false;       // start with the panels hidden (F1 toggles)
    int width = 1280, height = 720;
    SettingsOverrides overrides;
    std::vector<std::string> limits;   // --limit KEY=N load budgets
    std::string abView;                // --ab A.json: start in A/B compare with A from this view state
    std::string abMode = "side";       // --ab-mode side|wipe|diff
};

// Opens the window and runs until it is closed (or --frames ran); failures throw CLI::RuntimeError.
void runViewer(const ViewerOptions& options);

}  // namespace shadowlab::app
