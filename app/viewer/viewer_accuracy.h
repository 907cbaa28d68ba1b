#pragma once
// The viewer's side of the accuracy panel (ui/accuracy_panel.h): on request, the current view is
// measured for SSM, PSM and LiSPSM with the instruments of app/accuracy.h (and Embree ground truth
// with a BVH kept per scene), and the reports become the panel's plain data.
#include "accuracy.h"
#include "accuracy_panel.h"
#include "gl/gl_objects.h"

#include <memory>

namespace shadowlab::app {

struct ViewerAccuracy {
    ui::AccuracyView view;
    ui::AccuracyToggles toggles;
    bool requested = false;
    Settings measuredSettings;  // the mismatch view shows only while the view is still this one
    const Scene* raysScene = nullptr;  // the scene `rays` was built for
    double raysTime = 0.0;             // at this animation.time (its pose: moved and deformed meshes)
    std::unique_ptr<RayScene> rays;
    gl::Texture mismatch;  // the current method's mismatch picture
};

// Measures at width x height (capped at 1280 x 720). Leaves framebuffer 0 bound.
void measureForPanel(ViewerAccuracy& accuracy, Renderer& renderer, const Scene& scene, const Settings& settings,
                     int width, int height);

// The mismatch view: the current method's mismatch picture over the 3D view at (x, y) (top-left
// origin, framebuffer pixels), while the toggle is on and the settings are the measured ones.
void drawMismatchOverlay(const ViewerAccuracy& accuracy, const Settings& settings, float x, float y, float width,
                         float height);

// Whether `settings` still show what was measured (the shadow state depends on camera, light,
// method, cascades, map size, bias, filter, warp parameters and the scene time; not on overlays,
// compare layout or display settings).
bool stillMeasured(const ViewerAccuracy& accuracy, const Settings& settings);

// A new scene: the BVH and the figures belong to the old one.
void forgetScene(ViewerAccuracy& accuracy);

}  // namespace shadowlab::app
