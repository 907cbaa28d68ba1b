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
    bool groundTruth = true;
    bool requested = false;
    const Scene* raysScene = nullptr;  // the scene `rays` was built for
    std::unique_ptr<RayScene> rays;
    gl::Texture mismatch;  // the current method's mismatch picture
};

// Measures at width x height (capped at 1280 x 720). Leaves framebuffer 0 bound.
void measureForPanel(ViewerAccuracy& accuracy, Renderer& renderer, const Scene& scene, const Settings& settings,
                     int width, int height);

// A new scene: the BVH and the figures belong to the old one.
void forgetScene(ViewerAccuracy& accuracy);

}  // namespace shadowlab::app
