#pragma once
// View-state helpers shared by the viewer and its tests (GL-free, ImGui-free).
#include "settings/settings.h"

#include <ctime>
#include <string>
#include <vector>

namespace shadowlab::ui {

// The methods on screen: what the settings render (one map or cascades) alone, or the
// split-compare list (compare.count of them, each view its own choice; a plain "csm" resolved to
// csm.perSplit, so every cascaded choice names its parameterisation).
std::vector<MethodChoice> shownMethods(const Settings& settings);

// F12 screenshot name: shadowlab-<method>-<local time>.png, or shadowlab-ssm-vs-csm-lispsm-...
// for split views, so a picture says which methods it shows.
std::string screenshotFileName(const Settings& settings, std::time_t when);

}  // namespace shadowlab::ui
