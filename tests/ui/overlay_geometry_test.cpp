// What the overlays draw, without a GL context: the wireframes follow the toggles and the
// diagnostics, and the observer camera sees the view frustum and B from outside.
#include "overlays/overlay_geometry.h"

#include <gtest/gtest.h>

#include <cmath>

namespace shadowlab {
namespace {

ViewFrustum testView() {
    ViewFrustum v;
    v.eye = {0.0, 2.0, 10.0};
    v.forward = {0.0, 0.0, -1.0};
    v.fovY = glm::radians(60.0);
    v.aspect = 16.0 / 9.0;
    v.zNear = 0.1;
    v.zFar = 50.0;
    return v;
}

Aabb testBounds() { return Aabb{{-10.0, 0.0, -10.0}, {10.0, 3.0, 10.0}}; }

ShadowDiagnostics testDiagnostics() {
    ShadowSetup setup = computeShadowSetup(testView(), ShadowLight{}, testBounds(), ShadowParams{});
    EXPECT_TRUE(setup.valid) << setup.diagnostics.fallback;
    return setup.diagnostics;
}

std::size_t segmentCount(const std::vector<WireSet>& wires) {
    std::size_t n = 0;
    for (const WireSet& w : wires) n += w.segments.size();
    return n;
}

TEST(OverlayGeometry, PolygonEdgesCloseEveryLoopAndSkipBadPoints) {
    std::vector<glm::dvec3> segments;
    appendPolygonEdges({{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}}, segments);
    ASSERT_EQ(segments.size(), 6u);
    EXPECT_EQ(segments[4], glm::dvec3(1, 1, 0));
    EXPECT_EQ(segments[5], glm::dvec3(0, 0, 0));  // back to the start
    segments.clear();
    appendPolygonEdges({{{0, 0, 0}, {std::nan(""), 0, 0}, {1, 1, 0}}}, segments);
    EXPECT_EQ(segments.size(), 2u);  // only the edge between the two finite points
}

TEST(OverlayGeometry, WiresFollowTheToggles) {
    const ShadowDiagnostics d = testDiagnostics();
    OverlaySettings all;
    const auto everything = overlayWires(d, all, testView(), testBounds(), {0, -1, 0}, 0.1);
    OverlaySettings none;
    none.drawB = none.drawV = none.drawS = none.drawP = false;
    EXPECT_TRUE(overlayWires(d, none, testView(), testBounds(), {0, -1, 0}, 0.1).empty());
    // Each toggle alone contributes segments, and all together are the sum.
    std::size_t sum = 0;
    for (int i = 0; i < 4; ++i) {
        OverlaySettings one = none;
        (i == 0 ? one.drawB : i == 1 ? one.drawV : i == 2 ? one.drawS : one.drawP) = true;
        const std::size_t n = segmentCount(overlayWires(d, one, testView(), testBounds(), {0, -1, 0}, 0.1));
        EXPECT_GT(n, 0u) << "toggle " << i;
        sum += n;
    }
    EXPECT_EQ(segmentCount(everything), sum);
    // S is the box: 6 faces of 4 edges.
    OverlaySettings s = none;
    s.drawS = true;
    EXPECT_EQ(segmentCount(overlayWires(d, s, testView(), testBounds(), {0, -1, 0}, 0.1)), 48u);
}

TEST(OverlayGeometry, VAndSFallBackWhenThereIsNoShadowThisFrame) {
    OverlaySettings o;
    const auto wires = overlayWires(ShadowDiagnostics{}, o, testView(), testBounds(), {0, -1, 0}, 0.1);
    // B and P are empty without a shadow setup; V (frustum, 6 quads) and S (box) are still shown.
    EXPECT_EQ(segmentCount(wires), 48u + 48u);
}

TEST(OverlayGeometry, ObserverSeesTheCameraAndBFromOutside) {
    const ShadowDiagnostics d = testDiagnostics();
    const ViewFrustum view = testView();
    for (double yaw : {0.0, 90.0, -135.0}) {
        const ObserverCamera cam = observerCamera(d, view, testBounds(), yaw, 35.0, 1.0, 4.0 / 3.0);
        const glm::dmat4 vp = cam.viewProjection();
        auto insideClip = [&](const glm::dvec3& p) {
            const glm::dvec4 c = vp * glm::dvec4(p, 1.0);
            return c.w > 0.0 && std::abs(c.x) <= c.w * 1.0001 && std::abs(c.y) <= c.w * 1.0001 &&
                   std::abs(c.z) <= c.w * 1.0001;
        };
        EXPECT_TRUE(insideClip(view.eye)) << "yaw " << yaw;
        for (const Polygon& face : d.bodyB)
            for (const glm::dvec3& p : face) EXPECT_TRUE(insideClip(p)) << "yaw " << yaw;
        // The observer stands outside what it frames.
        EXPECT_GT(glm::distance(cam.eye, cam.target), cam.radius);
    }
    // Pitch 89 looks straight down without a degenerate look-at.
    const ObserverCamera top = observerCamera(d, view, testBounds(), 0.0, 89.0, 1.0, 1.0);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_TRUE(std::isfinite(top.view[i][j]));
}

// Per-split overlays of cascades: each split's frustum slice and B_i in the split's colour.
TEST(OverlayGeometry, CascadeWiresShowEverySplitsSliceAndBodyInItsColour) {
    CascadeParams params;
    params.splits = 3;
    const CascadeSetup cascades = computeCascadeSetup(testView(), ShadowLight{}, testBounds(), params);
    ASSERT_TRUE(cascades.error.empty()) << cascades.error;
    ASSERT_EQ(cascades.splits.size(), 3u);
    OverlaySettings o;
    const auto wires = cascadeWires(cascades, o, testView());
    ASSERT_EQ(wires.size(), 6u);  // slice + B_i per split
    for (int i = 0; i < 3; ++i) {
        const WireSet& slice = wires[std::size_t(2 * i)];
        const WireSet& body = wires[std::size_t(2 * i + 1)];
        EXPECT_EQ(body.color, cascadeColor(i));
        EXPECT_EQ(glm::vec3(slice.color), glm::vec3(cascadeColor(i)) * 0.6f);
        EXPECT_EQ(slice.segments.size(), 48u);  // a frustum: 6 quads
        // The slice lies between the split's depths along the view direction.
        for (const glm::dvec3& p : slice.segments) {
            const double z = glm::dot(p - testView().eye, glm::dvec3(0, 0, -1));
            EXPECT_GE(z, cascades.splits[std::size_t(i)].zNear - 1e-6);
            EXPECT_LE(z, cascades.splits[std::size_t(i)].zFar + 1e-6);
        }
        EXPECT_FALSE(body.segments.empty());
    }
    EXPECT_NE(cascadeColor(0), cascadeColor(1));
    EXPECT_EQ(cascadeColor(4), cascadeColor(0));
    // The toggles: V off keeps the bodies, B off the slices, both off nothing.
    o.drawV = false;
    EXPECT_EQ(cascadeWires(cascades, o, testView()).size(), 3u);
    o.drawB = false;
    EXPECT_TRUE(cascadeWires(cascades, o, testView()).empty());
    EXPECT_TRUE(cascadeWires(CascadeSetup{}, OverlaySettings{}, testView()).empty());
}

TEST(OverlayGeometry, TheObserverFramesTheBodiesOfAllSplits) {
    CascadeParams params;
    params.splits = 4;
    const CascadeSetup cascades = computeCascadeSetup(testView(), ShadowLight{}, testBounds(), params);
    ASSERT_EQ(cascades.splits.size(), 4u);
    const ShadowDiagnostics d = cascadeFramingDiagnostics(cascades);
    std::size_t faces = 0;
    for (const CascadeSplit& s : cascades.splits) faces += s.setup.diagnostics.bodyB.size();
    EXPECT_EQ(d.bodyB.size(), faces);
    const ObserverCamera cam = observerCamera(d, testView(), testBounds(), 35.0, 35.0, 1.0, 4.0 / 3.0);
    const glm::dmat4 vp = cam.viewProjection();
    for (const CascadeSplit& s : cascades.splits)
        for (const Polygon& face : s.setup.diagnostics.bodyB)
            for (const glm::dvec3& p : face) {
                const glm::dvec4 c = vp * glm::dvec4(p, 1.0);
                EXPECT_TRUE(c.w > 0.0 && std::abs(c.x) <= c.w * 1.0001 && std::abs(c.y) <= c.w * 1.0001);
            }
    EXPECT_TRUE(cascadeFramingDiagnostics(CascadeSetup{}).bodyB.empty());
}

}  // namespace
}  // namespace shadowlab
