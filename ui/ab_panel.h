#pragma once
// A/B compare of any two settings: the current settings stored as A, then anything changed is B;
// shown side by side, as a wipe or as a difference image. ImGui only; the viewer renders.
#include "settings/settings.h"

#include <optional>
#include <string>
#include <vector>

namespace shadowlab::ui {

enum class AbMode { SideBySide, Wipe, Difference };

struct AbCompare {
    std::optional<Settings> a;  // the stored snapshot; B is always the current settings
    bool active = false;
    AbMode mode = AbMode::SideBySide;
    double wipe = 0.5;       // fraction of the view width shown from A
    double diffScale = 4.0;  // gain of |A - B|
    bool sameCamera = true;  // render A with B's (the current) camera
    std::string lastDifference;  // statistics of the last difference image, for the panel
};

// The settings A is rendered with this frame.
Settings settingsForA(const AbCompare& ab, const Settings& current);

// "key: A value -> B value" for each setting A and B differ in (settings keys, as --set takes them).
std::vector<std::string> differingSettings(const Settings& a, const Settings& b);

// Returns true when the compare state changed (the viewer redraws).
bool drawAbPanel(AbCompare& ab, const Settings& current);

}  // namespace shadowlab::ui
