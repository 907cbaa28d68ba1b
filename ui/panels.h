#pragma once
// The viewer's parameter panels. Each is one small function that edits the shared Settings
// struct (the same struct --view JSON and --set fill) and reads plain data: frame stats, the shadow
// diagnostics, the scene model. No GL include reaches here; the viewer turns the edited settings
// into frames. Every function returns true when it changed a setting.
#include "frame/frame_stats.h"
#include "scenes/scene.h"
#include "settings/settings.h"

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace shadowlab::ui {

// Method panel: SSM (focused / unfocused), PSM, LiSPSM; shadows on/off; shadow map resolution.
bool drawMethodPanel(Settings& settings, const FrameStats& stats);
// LiSPSM panel (thesis 9.2.5, 9.2.6): virtual z_f (log slider) or auto, body vector, n override;
// read-outs n, n_opt (real and virtual far), gamma, d, z0, z1. `autoVirtualFar` is the z_f the
// auto mode picks this frame (shown while auto is on; NaN = unknown).
bool drawLispsmPanel(Settings& settings, const ShadowDiagnostics& diagnostics,
                     double autoVirtualFar = std::numeric_limits<double>::quiet_NaN());
// PSM panel (Stamminger & Drettakis 3, 4.2; thesis 7.2): read-outs of the move-back distance,
// the near-plane push and the light's kind in post-perspective space.
bool drawPsmPanel(Settings& settings, const ShadowDiagnostics& diagnostics);
// Bias panel (thesis ch. 5, 9.3): z-distribution, offset mode and parameters, back faces.
bool drawBiasPanel(Settings& settings);
// Filter & blur panel (thesis 4.3, 6.3, 9.4.2): nearest / PCF, blur, shadow-term-only view.
bool drawFilterPanel(Settings& settings);
// Light panel: the glTF lights, or a sun / spot by azimuth + elevation; the animated sun.
bool drawLightPanel(Settings& settings, const Scene& scene);
// Camera panel: fov, near, far, speed; the glTF cameras as presets.
bool drawCameraPanel(Settings& settings, const Scene& scene);

struct AnimationInfo {
    double duration = 0.0;  // longest glTF animation, seconds (0: none)
    int animations = 0;
    int channels = 0;
    struct Clip {
        std::string name;  // may be empty
        double duration = 0.0;
    };
    std::vector<Clip> clips;  // one per glTF animation (animation.clip picks one, -1 all)
};
// Animation panel: play / pause, speed, scrub (the scene clock also drives the animated sun).
bool drawAnimationPanel(Settings& settings, const AnimationInfo& info);

// The third-person observer of the overlay inset (viewer-local, not part of the view state).
struct ObserverView {
    double yawDeg = 35.0;    // around the view frustum, relative to the camera's back
    double pitchDeg = 35.0;  // above the horizon
    double distance = 1.0;   // x the distance that frames V, B and the camera
};
// Overlays panel: the insets (shadow map depth, light view, observer) and which of B, V, S, P
// their wireframes show.
bool drawOverlayPanel(Settings& settings, ObserverView& observer);
// Split compare: 1-3 views side by side with synchronised camera and light.
bool drawComparePanel(Settings& settings);

struct ViewStateRequests {
    bool save = false;
    bool load = false;
    bool screenshot = false;
};
struct ViewStateUi {
    char file[512] = "view.json";
    bool screenshotPanels = false;  // F12 saves the window with its panels, not only the rendered image
};
// View state panel: save / load the JSON that `shadowlab render --view` takes; screenshot.
ViewStateRequests drawViewStatePanel(ViewStateUi& ui);

struct FileUi;
struct AbCompare;
struct AccuracyView;
struct AccuracyToggles;
struct AccuracyRequest {
    bool measure = false;
};

// Everything the control window shows besides Settings.
struct ControlContext {
    const FrameStats* stats = nullptr;
    const Scene* scene = nullptr;
    AnimationInfo animation;
    double autoVirtualFar = std::numeric_limits<double>::quiet_NaN();  // LiSPSM auto z_f this frame
    ObserverView* observer = nullptr;
    ViewStateUi* viewState = nullptr;
    FileUi* file = nullptr;
    const AccuracyView* accuracy = nullptr;  // the accuracy panel's figures (ui/accuracy_panel.h)
    AccuracyToggles* accuracyToggles = nullptr;
    // In split compare: the stats of the view that shows LiSPSM / PSM, so their read-outs are that
    // view's own (nullptr: `stats`).
    const FrameStats* lispsmStats = nullptr;
    const FrameStats* psmStats = nullptr;
    AbCompare* ab = nullptr;  // A/B compare of two settings (ui/ab_panel.h)
};
struct ControlResult {
    bool changed = false;
    ViewStateRequests requests;
    AccuracyRequest accuracy;  // "measure this view"
    std::string openFile;  // File > Open, a recent file, or "load view": the viewer opens it by its kind
    bool collapsed = false;  // folded to its title bar (its arrow): the 3D area may take the full width
};
// The control window (right edge of a `width` x `height` framebuffer): every panel above as a
// collapsing section.
ControlResult drawControlWindow(Settings& settings, const ControlContext& context, float width, float height);

// Width of the control window, so the viewer keeps its 3D views and insets out from under it.
float controlWindowWidth();

// The "keys and mouse" help of the View state panel, one control per line.
extern const char* const kKeysHelp;

// Buttons as wide as their labels, in rows that wrap at `lineWidth` (fixed half-width
// buttons would cut long camera names). A label wider than a whole line is shortened with
// "..." to fit. Pure layout, for the camera presets and their test.
struct FlowItem {
    int row = 0;
    float x = 0.0f, width = 0.0f;  // from the line's start
    std::string shown;             // the label, or its shortened form
};
// `textWidth` measures a string; `padding`: a button's width beyond its text; `spacing` between buttons.
std::vector<FlowItem> flowLayout(const std::vector<std::string>& labels, float lineWidth, float padding,
                                 float spacing, const std::function<float(const std::string&)>& textWidth);

// A caption drawn over the 3D image (compare views, insets), behind the ImGui windows.
struct Caption {
    float x = 0, y = 0;  // top-left, framebuffer pixels from the top-left corner
    std::string text;
};
void drawCaptions(const std::vector<Caption>& captions);

}  // namespace shadowlab::ui
