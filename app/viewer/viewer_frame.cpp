#include "viewer/viewer_frame.h"

#include "settings/method_choice.h"
#include "view_state.h"
#include "widgets.h"

#include <algorithm>
#include <chrono>

namespace shadowlab::app {

InsetRect toGl(const InsetRect& r, int fbHeight) { return {r.x, fbHeight - r.y - r.height, r.width, r.height}; }

bool contains(const InsetRect& r, double x, double y) {
    return !r.empty() && x >= r.x && x < r.x + r.width && y >= r.y && y < r.y + r.height;
}

std::vector<Pane> splitPanes(const Settings& settings) {
    const std::vector<MethodChoice> choices = ui::shownMethods(settings);
    if (choices.size() <= 1) return {Pane{settings, ""}};
    // Each view renders its own choice (one map, or cascades with its parameterisation per split:
    // csm-ssm | csm-lispsm), whatever the Method panel's method and csm.enabled say.
    std::vector<Pane> panes;
    for (const MethodChoice& choice : choices) {
        Pane p{settings, ""};
        applyMethodChoice(p.settings, choice);
        p.caption = methodChoiceName(methodChoiceOf(p.settings));
        panes.push_back(std::move(p));
    }
    return panes;
}

InsetKind insetAt(const Layout& layout, double x, double y) {
    if (contains(layout.shadowMapInset, x, y)) return InsetKind::ShadowMap;
    if (contains(layout.lightViewInset, x, y)) return InsetKind::LightView;
    if (contains(layout.observerInset, x, y)) return InsetKind::Observer;
    return InsetKind::None;
}

ui::ScreenArea statsArea(const Layout& layout, float top) {
    constexpr float kGap = 6.0f;
    const float y0 = std::max(top, 36.0f);
    float insetTop = float(layout.fbHeight), insetRight = 0.0f;
    for (const InsetRect* r : {&layout.shadowMapInset, &layout.lightViewInset, &layout.observerInset})
        if (!r->empty()) {
            insetTop = std::min(insetTop, float(r->y) - kGap);
            insetRight = std::max(insetRight, float(r->x + r->width) + kGap);
        }
    const ui::ScreenArea above{0.0f, y0, float(layout.viewWidth), std::max(y0, insetTop)};
    const ui::ScreenArea beside{std::min(insetRight, float(layout.viewWidth)), y0, float(layout.viewWidth),
                                std::max(y0, float(layout.fbHeight) - kGap)};
    // Above the insets while that holds the window's first lines (it does not move when an inset
    // is switched on); beside them under an enlarged inset, which reaches the top.
    constexpr float kEnoughHeight = 160.0f;
    if (above.y1 - above.y0 >= kEnoughHeight) return above;
    auto area = [](const ui::ScreenArea& r) { return (r.x1 - r.x0) * (r.y1 - r.y0); };
    return area(beside) > area(above) ? beside : above;
}

Layout layoutFrame(int fbWidth, int fbHeight, bool showUi, const Settings& settings, int paneCount,
                   InsetKind enlarged) {
    Layout l;
    l.fbWidth = fbWidth;
    l.fbHeight = fbHeight;
    l.viewWidth = showUi ? std::max(16, fbWidth - int(ui::controlWindowWidth())) : fbWidth;
    const int count = paneCount > 0 ? paneCount : int(ui::shownMethods(settings).size());
    for (int i = 0; i < count; ++i) {
        const int x0 = l.viewWidth * i / count, x1 = l.viewWidth * (i + 1) / count;
        l.views.push_back({x0, 0, std::max(1, x1 - x0 - (i + 1 < count ? 2 : 0)), fbHeight});
    }
    // Insets along the bottom edge of the 3D area, left to right, as many as are switched on.
    const int margin = 12;
    const double size = std::clamp(settings.overlays.insetSize, 0.5, 2.5);
    const int side = std::max(64, int(size * std::min({fbHeight / 3, l.viewWidth / 4, 360})));
    const int bigSide = std::max(side, std::min(fbHeight - 2 * margin, (l.viewWidth - 2 * margin) * 3 / 4));
    struct Slot {
        InsetRect* rect;
        bool on;
        InsetKind kind;
        int aspectNum, aspectDen;  // width : height
        int squares = 1;           // with cascades: one square per layer, side by side, kLayerGap apart
        int width(int height) const {
            return height * aspectNum / aspectDen * squares + kLayerGap * (squares - 1);
        }
    };
    // The insets show the left view: in a split compare its own choice, one map or cascades.
    const int layers = ui::shownMethods(settings).front().cascaded ? std::clamp(settings.csm.splits, 1, 4) : 1;
    std::vector<Slot> slots = {{&l.shadowMapInset, settings.overlays.shadowMapInset, InsetKind::ShadowMap, 1, 1, layers},
                               {&l.lightViewInset, settings.overlays.lightViewInset, InsetKind::LightView, 1, 1, layers},
                               {&l.observerInset, settings.overlays.observerInset, InsetKind::Observer, 4, 3}};
    // The enlarged inset first, at the left edge (at 4:3 and 3/4 of the width it still fits).
    std::stable_partition(slots.begin(), slots.end(), [&](const Slot& s) { return s.kind == enlarged; });
    // Without an enlarged inset all must fit in one row: shrink them together when they do not
    // (cascade layers side by side make the shadow-map and light-view insets wide).
    int smallSide = side;
    if (enlarged == InsetKind::None) {
        int used = 0, gaps = 0, count = 0;
        for (const Slot& slot : slots)
            if (slot.on) {
                used += slot.width(side);
                gaps += kLayerGap * (slot.squares - 1);
                ++count;
            }
        const int avail = l.viewWidth - 2 * margin - std::max(0, count - 1) * (margin + 4);
        if (used > avail && used > gaps)
            smallSide = std::max(16, int(double(side) * double(avail - gaps) / double(used - gaps)));
    }
    int x = margin;
    for (const Slot& slot : slots) {
        if (!slot.on) continue;
        int height = slot.kind == enlarged ? bigSide : smallSide;
        if (slot.kind == enlarged && slot.squares > 1)
            height = std::min(height, (l.viewWidth - 2 * margin - kLayerGap * (slot.squares - 1)) / slot.squares);
        const int width = slot.width(height);
        // Beside an enlarged inset the small ones are left out once they no longer fit.
        if (enlarged != InsetKind::None && slot.kind != enlarged && x + width > l.viewWidth - margin) continue;
        *slot.rect = {x, fbHeight - height - margin, width, height};
        x += width + margin + 4;
    }
    return l;
}

namespace {

using Clock = std::chrono::steady_clock;

// The scene as the light sees it through `setup`'s matrix, with the overlay wires in it.
void drawLightView(const OverlayRenderer& overlays, const Renderer& renderer, const Scene& scene, const InsetRect& r,
                   const ShadowSetup& setup, const Settings& settings, const ViewFrustum& view,
                   const glm::dvec3& lightDirection) {
    const glm::dmat4& m = setup.worldToShadowClip;  // w > 0 over B by contract
    overlays.drawScene(0, r, scene, *renderer.gpuScene(), m, lightDirection, setup.reverseDepthTest);
    const double marker = 0.02 * std::max(1e-3, glm::length(setup.bodyBounds.extent()));
    overlays.drawWires(0, r, overlayWires(setup.diagnostics, settings.overlays, view, scene.bounds, lightDirection, marker),
                       m);
}

void drawInsets(FrameTools tools, const Scene& scene, const Settings& settings, const Layout& layout,
                const ui::ObserverView& observerView, ViewsResult& result, double seconds) {
    Renderer& renderer = tools.renderer;
    OverlayRenderer& overlays = tools.overlays;
    const int fbHeight = layout.fbHeight;
    const ViewFrustum viewFrustum0 =
        viewFrustum(settings.camera, double(layout.views[0].width) / std::max(1, layout.views[0].height));
    const LightFrame light = resolveLight(scene, settings.light, seconds);
    const bool haveMap = result.stats.shadowMapSize > 0 && renderer.lastShadowSetup().valid;
    const ShadowSetup& setup = renderer.lastShadowSetup();
    // Cascades: every layer in the shadow-map inset, every split's slice and B_i in the
    // observer, in the split colours of csm.colorSplits; the light view of every split side by side.
    const CascadeSetup& cascades = renderer.lastCascadeSetup();
    const bool cascaded = !cascades.splits.empty() && renderer.cascadeMapTexture() != 0;
    auto noteFor = [&](const InsetRect& r, const std::string& title) {
        result.captions.push_back({float(r.x + 4), float(r.y + 4), title});
    };
    if (!layout.shadowMapInset.empty()) {
        const InsetRect r = toGl(layout.shadowMapInset, fbHeight);
        overlays.drawFrame(0, r);
        const glm::vec2 window{float(settings.overlays.depthWindowLow), float(settings.overlays.depthWindowHigh)};
        if (haveMap && cascaded)
            overlays.drawDepthLayersInset(0, r, renderer.cascadeMapTexture(), renderer.cascadeMapLayers(), window);
        else if (haveMap)
            overlays.drawDepthInset(0, r, renderer.shadowMapTexture(), setup.reverseDepthTest, window);
        noteFor(layout.shadowMapInset, !haveMap  ? "no shadow map"
                                       : cascaded ? "shadow map layers, near to far"
                                                  : "shadow map");
    }
    if (!layout.lightViewInset.empty()) {
        const InsetRect r = toGl(layout.lightViewInset, fbHeight);
        overlays.drawFrame(0, r);
        if (haveMap && renderer.gpuScene() && cascaded) {
            const std::vector<InsetRect> squares = layerSquares(r, int(cascades.splits.size()));
            for (std::size_t i = 0; i < squares.size(); ++i)
                if (cascades.splits[i].setup.valid)
                    drawLightView(overlays, renderer, scene, squares[i], cascades.splits[i].setup, settings,
                                  viewFrustum0, light.direction);
        } else if (haveMap && renderer.gpuScene()) {
            drawLightView(overlays, renderer, scene, r, setup, settings, viewFrustum0, light.direction);
        }
        noteFor(layout.lightViewInset, !haveMap ? "no light view" : cascaded ? "light views, near to far" : "light view");
    }
    if (!layout.observerInset.empty() && renderer.gpuScene()) {
        const InsetRect r = toGl(layout.observerInset, fbHeight);
        overlays.drawFrame(0, r);
        // With cascades the framing covers every B_i, and B and V are drawn per split.
        const ShadowDiagnostics d = cascaded ? cascadeFramingDiagnostics(cascades) : result.stats.shadow;
        const ObserverCamera observer =
            observerCamera(d, viewFrustum0, scene.bounds, observerView.yawDeg, observerView.pitchDeg,
                           observerView.distance, double(r.width) / double(r.height));
        overlays.drawScene(0, r, scene, *renderer.gpuScene(), observer.viewProjection(), light.direction, false);
        OverlaySettings shared = settings.overlays;
        if (cascaded) shared.drawB = shared.drawV = false;
        std::vector<WireSet> wires =
            overlayWires(d, shared, viewFrustum0, scene.bounds, light.direction, observer.radius * 0.04);
        if (cascaded)
            for (WireSet& w : cascadeWires(cascades, settings.overlays, viewFrustum0)) wires.push_back(std::move(w));
        overlays.drawWires(0, r, wires, observer.viewProjection());
        noteFor(layout.observerInset, "observer");
    }
}

PaneError paneError(const MeasureFrame& measured, const InsetRect& pane, const glm::dvec2& cursor) {
    PaneError e;
    e.stats = footprintStats(measured.footprint);
    if (contains(pane, cursor.x, cursor.y) && measured.width == pane.width && measured.height == pane.height) {
        const int x = int(cursor.x) - pane.x;
        const int row = pane.height - 1 - (int(cursor.y) - pane.y);  // MeasureFrame rows are bottom-up
        e.cursorInside = true;
        e.cursorValue = measured.footprint[std::size_t(row) * std::size_t(pane.width) + std::size_t(x)];
    }
    return e;
}

}  // namespace

void addErrorCaptions(const ViewsResult& views, const Layout& layout, const glm::dvec2& cursor,
                      std::vector<ui::Caption>& captions) {
    for (std::size_t i = 0; i < views.errors.size() && i < layout.views.size(); ++i) {
        const PaneError& e = views.errors[i];
        const InsetRect& pane = layout.views[i];
        const std::string line = e.stats.measuredPixels == 0
                                     ? std::string("no receivers measured")
                                     : "px/texel  median " + ui::formatNumber(e.stats.median, 3) + "  p95 " +
                                           ui::formatNumber(e.stats.p95, 3) + "  >1: " +
                                           ui::formatNumber(100.0 * e.stats.undersampledFraction, 3) + "%";
        captions.push_back({float(pane.x + 8), float(pane.y + pane.height - 24), line});
        if (e.cursorInside)
            captions.push_back({float(cursor.x + 14), float(cursor.y + 10),
                                e.cursorValue > 0.0f ? ui::formatNumber(e.cursorValue, 3) + " px/texel"
                                                     : std::string("not measured")});
    }
}

ViewsResult drawViews(FrameTools tools, const Scene& scene, const std::vector<Pane>& panes, const Layout& layout,
                      const ui::ObserverView& observer, const glm::dvec2& cursor) {
    ViewsResult result;
    const Settings& settings = panes.back().settings;  // the current settings (B in an A/B compare)
    const int fbHeight = layout.fbHeight;
    const double seconds = settings.animation.time;
    // The area right of the views (under the control window) is cleared once.
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, layout.fbWidth, layout.fbHeight);
    const GLfloat clear[4] = {0.08f, 0.08f, 0.09f, 1.0f};
    glClearBufferfv(GL_COLOR, 0, clear);
    // Right to left, so the left view (whose shadow map and setup the insets show) is rendered last.
    const int count = int(std::min(panes.size(), layout.views.size()));
    result.paneStats.resize(std::size_t(count));
    const bool measured = settings.viewMode == ViewMode::AliasingError;
    if (measured) result.errors.resize(std::size_t(count));
    for (int i = count - 1; i >= 0; --i) {
        const Settings& view = panes[std::size_t(i)].settings;
        const InsetRect r = toGl(layout.views[std::size_t(i)], fbHeight);
        tools.timer.begin(i);
        FrameStats viewStats;
        if (measured) {
            // The heat map and, from the same frame, the float footprint per pixel for the numbers.
            MeasureFrame frame;
            viewStats = tools.renderer.renderMeasured(scene, view, seconds, Viewport{0, r.x, r.y, r.width, r.height},
                                                      frame);
            result.errors[std::size_t(i)] = paneError(frame, layout.views[std::size_t(i)], cursor);
        } else {
            viewStats = tools.renderer.render(scene, view, seconds, Viewport{0, r.x, r.y, r.width, r.height});
        }
        tools.timer.end(i);
        const std::string& caption = panes[std::size_t(i)].caption;
        if (!caption.empty()) {
            result.captions.push_back({float(layout.views[std::size_t(i)].x + 8), 8.0f, caption});
            result.compareLines.insert(result.compareLines.begin(),
                                       caption + ": GPU " + ui::formatNumber(tools.timer.lastMs(i), 3) +
                                           " ms, casters " + std::to_string(viewStats.castersDrawn) + " (culled " +
                                           std::to_string(viewStats.castersCulled) + ")");
        }
        result.paneStats[std::size_t(i)] = viewStats;
        if (i == 0) result.stats = std::move(viewStats);
    }

    const auto overlayStart = Clock::now();
    tools.timer.begin(kOverlaySection);
    drawInsets(tools, scene, settings, layout, observer, result, seconds);
    tools.timer.end(kOverlaySection);
    tools.timer.endFrame();
    if (!layout.shadowMapInset.empty() || !layout.lightViewInset.empty() || !layout.observerInset.empty())
        result.stats.passes.push_back({"overlays",
                                       std::chrono::duration<double, std::milli>(Clock::now() - overlayStart).count(),
                                       tools.timer.lastMs(kOverlaySection)});
    return result;
}

}  // namespace shadowlab::app
