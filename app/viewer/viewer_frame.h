#pragma once
// One frame of the viewer's 3D area: where the split views and insets go (Layout), and drawing
// them with the Renderer and the OverlayRenderer. The ImGui panels are drawn elsewhere.
#include "measure/aliasing_stats.h"
#include "overlays/overlay.h"
#include "gl/overlay_timer.h"
#include "panels.h"
#include "stats_panel.h"
#include "renderer.h"

#include <string>
#include <vector>

namespace shadowlab::app {

// Screen layout of one frame, in framebuffer pixels with the origin at the TOP-left (ImGui's);
// toGl() flips a rectangle to GL's bottom-left origin.
struct Layout {
    int fbWidth = 0, fbHeight = 0;
    int viewWidth = 0;             // the 3D area: left of the control window
    std::vector<InsetRect> views;  // top-left origin
    InsetRect shadowMapInset, lightViewInset, observerInset;
};

InsetRect toGl(const InsetRect& r, int fbHeight);
bool contains(const InsetRect& r, double x, double y);

// An inset of the 3D area; a click on one enlarges it, a second click shrinks it.
enum class InsetKind { None, ShadowMap, LightView, Observer };
InsetKind insetAt(const Layout& layout, double x, double y);

// `paneCount`: views side by side (0: as many as the split-compare methods). `enlarged`: that
// inset as large as the 3D area allows (its height: the area's less the margins, at most 3/4 of
// its width), the others at their size beside it while they fit.
Layout layoutFrame(int fbWidth, int fbHeight, bool showUi, const Settings& settings, int paneCount = 0,
                   InsetKind enlarged = InsetKind::None);

// Where the Stats window may go: the part of the 3D area below `top` (the notification area's
// bottom, at least 36 px, under the split views' captions) that no inset or inset title
// covers: above the inset row while that is at least 160 px tall, else right of the insets (an
// enlarged inset reaches the top).
ui::ScreenArea statsArea(const Layout& layout, float top);

// One view of the frame: the settings it is rendered with and its caption ("" for none).
struct Pane {
    Settings settings;
    std::string caption;
};
// The split-compare views of `settings` (one pane when split compare is off). With csm on, only
// the first view of settings.method renders cascades (captioned "csm-..."), the others one map.
std::vector<Pane> splitPanes(const Settings& settings);

// The aliasing error of one split view, live while the aliasing view is on (item "numbers on
// screen"): the texel-footprint statistics of its measured receivers and the value under the cursor.
struct PaneError {
    AliasingStats stats;
    bool cursorInside = false;
    float cursorValue = 0.0f;  // pixels per texel; 0 = no receiver measured there
};

// What one frame of views reports back to the panels.
struct ViewsResult {
    std::vector<PaneError> errors;         // per split view, only in ViewMode::AliasingError
    FrameStats stats;                      // the left view's (its setup is what the insets show)
    std::vector<FrameStats> paneStats;     // one per split view, left to right
    std::vector<ui::Caption> captions;     // method names over split views, inset titles
    std::vector<std::string> compareLines;
};

// GPU time of each split view (sections 0-2) and of the overlays (section 3).
constexpr int kOverlaySection = 3;
constexpr int kFrameSections = 4;

struct FrameTools {
    Renderer& renderer;
    OverlayRenderer& overlays;
    SectionTimer& timer;
};

// Clears the window and draws every split view and the switched-on insets. `cursor`: framebuffer
// pixels, top-left origin (for the error read-out under it).
ViewsResult drawViews(FrameTools tools, const Scene& scene, const std::vector<Pane>& panes, const Layout& layout,
                      const ui::ObserverView& observer, const glm::dvec2& cursor);

// Captions with each pane's error statistics and the value under the cursor.
void addErrorCaptions(const ViewsResult& views, const Layout& layout, const glm::dvec2& cursor,
                      std::vector<ui::Caption>& captions);

}  // namespace shadowlab::app
