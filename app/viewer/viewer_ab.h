#pragma once
// The viewer's A/B compare (ui/ab_panel.h): A | B as two panes, or A and B rendered offscreen at
// the size of the 3D area and shown as a wipe or as their difference (renderer/image/image_compare.h,
// the same images `render --compare` writes).
#include "ab_panel.h"
#include "resources/render_target.h"
#include "viewer/viewer_frame.h"

#include <memory>

namespace shadowlab::app {

// The panes of the frame: A and B side by side when the compare shows A | B, else the split views.
std::vector<Pane> framePanes(const ui::AbCompare& ab, const Settings& current);

// Offscreen targets of the wipe and difference views, kept between frames.
struct AbTargets {
    std::unique_ptr<RenderTarget> a, b;
    gl::Texture composed;
    gl::Framebuffer composedFramebuffer;
    int width = 0, height = 0;
};

// True when the compare replaces the normal views this frame (wipe or difference).
bool abComposites(const ui::AbCompare& ab);

// Renders A and B offscreen, composes them (wipe or difference) and shows the result over the 3D
// area of `layout`, with captions. Returns B's stats.
FrameStats drawAbComposite(Renderer& renderer, const Scene& scene, const Settings& current, const Layout& layout,
                           ui::AbCompare& ab, AbTargets& targets, std::vector<ui::Caption>& captions);

}  // namespace shadowlab::app
