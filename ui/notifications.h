#pragma once
// The notification area: a strip at the top of the 3D area that no panel covers (the Stats
// window is placed below it, see statsArea). Errors and clamping notices stay until dismissed;
// an info message ("saved shot.png (1280x720) in DIR") shows kInfoSeconds, then fades out; the
// load progress shows while a scene loads. ImGui only, never GL.
#include "stats_panel.h"

#include <string>

namespace shadowlab::ui {

struct LoadingInfo {
    bool active = false;
    std::string file;
    double seconds = 0.0;
    bool uploading = false;  // parsed; the GPU upload runs this frame
    double fraction = 0.0;   // the loader's progress, 0 .. 1 (or of the textures)
    bool textures = false;   // the scene shows; its textures stream in (fraction: uploaded share)
};

// Seconds an info message stays fully visible, then seconds it takes to fade.
constexpr double kInfoSeconds = 4.0;
constexpr double kInfoFadeSeconds = 1.0;

// Whether the area shows something that changes without input (a fading message): the viewer
// keeps drawing frames while it does.
bool notificationsFading(const ViewerStatus& status);

// Draws the area at the top of the 3D area (x0 .. x0 + width), in front of every window, at time
// `now` (seconds). Dismissing clears the error and the notices in `status`; an info message
// older than kInfoSeconds + kInfoFadeSeconds is cleared. Returns the y below the area (its top
// when nothing is shown), where the windows over the 3D area may begin.
float drawNotifications(ViewerStatus& status, const LoadingInfo& loading, float x0, float width, double now);

}  // namespace shadowlab::ui
