#pragma once
// Display panel: exposure, tone mapping, hemisphere ambient, MSAA of the lit view. ImGui only.
#include "settings/settings.h"

namespace shadowlab::ui {

bool drawDisplayPanel(Settings& settings);

}  // namespace shadowlab::ui
