#include "viewer/viewer_ab.h"

#include "image/image_compare.h"
#include "widgets.h"

#include <algorithm>
#include <cstdio>

namespace shadowlab::app {

std::vector<Pane> framePanes(const ui::AbCompare& ab, const Settings& current) {
    if (ab.active && ab.a && ab.mode == ui::AbMode::SideBySide) {
        Settings b = current;
        b.compare.count = 1;
        return {Pane{ui::settingsForA(ab, current), "A"}, Pane{b, "B"}};
    }
    return splitPanes(current);
}

bool abComposites(const ui::AbCompare& ab) { return ab.active && ab.a && ab.mode != ui::AbMode::SideBySide; }

namespace {

void ensureTargets(AbTargets& t, int width, int height) {
    if (t.a && t.width == width && t.height == height) return;
    t.a = std::make_unique<RenderTarget>(width, height);
    t.b = std::make_unique<RenderTarget>(width, height);
    t.composed = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.composed.id(), 1, GL_RGBA8, width, height);  // holds sRGB-encoded bytes as they are
    t.composedFramebuffer = gl::createFramebuffer();
    glNamedFramebufferTexture(t.composedFramebuffer.id(), GL_COLOR_ATTACHMENT0, t.composed.id(), 0);
    t.width = width;
    t.height = height;
}

// Shows `image` (top row first) over the window's [0, width) x [0, height) with one blit.
void show(const AbTargets& t, const RgbaImage& image) {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(t.composed.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                        image.pixels.data());
    glDisable(GL_FRAMEBUFFER_SRGB);
    // Destination rows flipped: the image's top row goes to the window's top.
    glBlitNamedFramebuffer(t.composedFramebuffer.id(), 0, 0, 0, image.width, image.height, 0, image.height,
                           image.width, 0, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

}  // namespace

FrameStats drawAbComposite(Renderer& renderer, const Scene& scene, const Settings& current, const Layout& layout,
                           ui::AbCompare& ab, AbTargets& targets, std::vector<ui::Caption>& captions) {
    const int width = std::max(16, layout.viewWidth), height = std::max(16, layout.fbHeight);
    ensureTargets(targets, width, height);
    Settings a = ui::settingsForA(ab, current), b = current;
    b.compare.count = 1;
    const double seconds = current.animation.time;
    renderer.render(scene, a, seconds, Viewport{targets.a->framebuffer(), 0, 0, width, height});
    const FrameStats stats = renderer.render(scene, b, seconds, Viewport{targets.b->framebuffer(), 0, 0, width, height});
    const RgbaImage imageA = targets.a->readColor(), imageB = targets.b->readColor();
    if (ab.mode == ui::AbMode::Wipe) {
        const int x = int(ab.wipe * width);
        RgbaImage wiped = wipeImage(imageA, imageB, x);
        for (int y = 0; y < height; ++y)  // the wipe line
            for (int dx = -1; dx <= 0; ++dx)
                if (x + dx >= 0 && x + dx < width)
                    for (int c = 0; c < 3; ++c) wiped.pixels[(std::size_t(y) * width + std::size_t(x + dx)) * 4 + c] = 255;
        show(targets, wiped);
        captions.push_back({8.0f, 8.0f, "A"});
        captions.push_back({float(std::min(x + 8, width - 24)), 8.0f, "B"});
    } else {
        const ImageDifference diff = differenceImage(imageA, imageB, ab.diffScale);
        show(targets, diff.image);
        char line[160];
        std::snprintf(line, sizeof line, "|A - B| x%.0f: max %d/255, mean %.3f, %.2f%% of pixels differ", ab.diffScale,
                      diff.maxChannelDifference, diff.meanChannelDifference, 100.0 * diff.differingFraction);
        ab.lastDifference = line;
        captions.push_back({8.0f, 8.0f, line});
    }
    return stats;
}

}  // namespace shadowlab::app
