#pragma once
// The "Skips" panel: each piece of work the renderer skips when a frame does not need
// it can be switched off here, to compare cost and to see that the picture does not change.
#include "settings/settings.h"

namespace shadowlab::ui {

bool drawSkipPanel(Settings& settings);

}  // namespace shadowlab::ui
