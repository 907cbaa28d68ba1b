// Which receivers a LiSPSM split's warp search measures (math/cascades.cpp, splitReceivers): a
// street canyon, ray cast at the depth pre-pass's coarse (8 x 6) and fine (32 x 24) grids, with
// the sun low behind the viewer grazing one wall, as on the generated street's
// Camera_DownStreet_SunBehind view, where split 1's search over its few coarse points chose a
// warp three times worse (split p99) than a fixed one.
#include "math/cascades.h"
#include "math/lispsm_search.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowlab {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kHalfWidth = 12.0, kWallHeight = 20.0, kLength = 1000.0;

ViewFrustum streetView() {
    ViewFrustum v;
    v.eye = {0.0, 1.7, 0.0};
    v.forward = glm::normalize(glm::dvec3(0.0, -0.05, -1.0));
    v.fovY = 60.0 * kPi / 180.0;
    v.aspect = 16.0 / 9.0;
    v.zNear = 0.1;
    v.zFar = 1200.0;
    return v;
}

// The street's directions: towards the sun 25 deg up, behind the viewer and a little to the
// left, so the right wall (normal -x) is lit at 7 deg, the left one faces away.
ShadowLight lowSunBehind() {
    ShadowLight l;
    l.direction = -glm::normalize(glm::dvec3(-0.126, 0.423, 0.897));
    return l;
}

Aabb streetBounds() {
    Aabb b;
    b.min = {-kHalfWidth, 0.0, -kLength};
    b.max = {kHalfWidth, kWallHeight, 1.0};
    return b;
}

// The surfaces seen at the centres of a gx x gy pixel grid: road (y = 0) and the two walls.
std::vector<SurfacePoint> castGrid(const ViewFrustum& v, int gx, int gy) {
    const glm::dvec3 f = glm::normalize(v.forward);
    const glm::dvec3 right = glm::normalize(glm::cross(f, glm::dvec3(0, 1, 0)));
    const glm::dvec3 up = glm::cross(right, f);
    const double ty = std::tan(0.5 * v.fovY), tx = ty * v.aspect;
    std::vector<SurfacePoint> out;
    for (int j = 0; j < gy; ++j)
        for (int i = 0; i < gx; ++i) {
            const double sx = (2.0 * i + 1.0) / gx - 1.0, sy = 1.0 - (2.0 * j + 1.0) / gy;
            const glm::dvec3 d = f + right * (sx * tx) + up * (sy * ty);
            double best = std::numeric_limits<double>::infinity();
            glm::dvec3 normal{0.0};
            if (d.y < 0.0) {
                best = -v.eye.y / d.y;
                normal = {0, 1, 0};
            }
            if (d.x != 0.0) {
                const double t = ((d.x > 0.0 ? kHalfWidth : -kHalfWidth) - v.eye.x) / d.x;
                const double y = v.eye.y + t * d.y;
                if (t > 0.0 && t < best && y >= 0.0 && y <= kWallHeight) {
                    best = t;
                    normal = {d.x > 0.0 ? -1.0 : 1.0, 0.0, 0.0};
                }
            }
            const glm::dvec3 p = v.eye + best * d;
            if (std::isfinite(best) && p.z > -kLength) out.push_back({p, normal});
        }
    return out;
}

double eyeDepth(const ViewFrustum& v, const glm::dvec3& p) { return glm::dot(p - v.eye, glm::normalize(v.forward)); }

CascadeParams streetCascade(const std::vector<SurfacePoint>& coarse, const std::vector<SurfacePoint>& fine,
                            const ViewFrustum& v) {
    CascadeParams p;
    p.splits = 4;
    p.lambda = 1.0;
    p.perSplit = SplitParameterization::Lispsm;
    p.mapResolution = 1024;
    p.base.collectPolygons = false;
    p.base.receiverPoints = coarse;
    p.base.fineReceiverPoints = fine;
    p.visibleNear = std::numeric_limits<double>::infinity();
    p.visibleFar = 0.0;
    for (const SurfacePoint& r : castGrid(v, ShadowParams::kFineReceiverGridX, ShadowParams::kFineReceiverGridY)) {
        p.visibleNear = std::min(p.visibleNear, eyeDepth(v, r.point));
        p.visibleFar = std::max(p.visibleFar, eyeDepth(v, r.point));
    }
    return p;
}

// Split 1's largest footprint over the fine grid's receivers in it (lit, not grazed: the ones the
// search counts), the dense stand-in for the rendered frame's worst pixels.
double splitOneWorstOverFine(const CascadeSetup& cs, const ViewFrustum& v, const ShadowLight& light,
                             const std::vector<SurfacePoint>& fine) {
    std::vector<SurfacePoint> inSplit;
    for (const SurfacePoint& r : fine)
        if (eyeDepth(v, r.point) < cs.splits[0].zFar) inSplit.push_back(r);
    const auto samples = detail::measuredReceiverSamples(light, inSplit);
    EXPECT_GT(samples.size(), 100u);
    return detail::worstFootprintOf(cs.splits[0].setup.worldToShadowClip, v, samples);
}

TEST(CascadeReceivers, ALispsmSplitSearchesTheFineGridOfItsRange) {
    const ViewFrustum view = streetView();
    const ShadowLight light = lowSunBehind();
    const std::vector<SurfacePoint> coarse = castGrid(view, ShadowParams::kReceiverGridX, ShadowParams::kReceiverGridY);
    const std::vector<SurfacePoint> fine =
        castGrid(view, ShadowParams::kFineReceiverGridX, ShadowParams::kFineReceiverGridY);
    const CascadeSetup withFine = computeCascadeSetup(view, light, streetBounds(), streetCascade(coarse, fine, view));
    const CascadeSetup coarseOnly = computeCascadeSetup(view, light, streetBounds(), streetCascade(coarse, {}, view));
    ASSERT_EQ(withFine.splits.size(), 4u);
    ASSERT_TRUE(withFine.splits[0].setup.valid && coarseOnly.splits[0].setup.valid);
    // Every fine receiver of the range is a sample (none is grazed below N.L 0.1 here).
    int inSplit = 0;
    for (const SurfacePoint& r : fine)
        inSplit += eyeDepth(view, r.point) < withFine.splits[0].zFar && glm::dot(r.normal, -light.direction) > 0.1;
    EXPECT_EQ(withFine.splits[0].setup.diagnostics.warpSamples, inSplit);

    // The best fixed n for split 1, over the same dense receivers.
    double bestFixed = std::numeric_limits<double>::infinity(), bestN = 0.0;
    for (double n : {0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 1e3, 1e5}) {
        CascadeParams p = streetCascade(coarse, fine, view);
        p.base.lispsm.overrideN = true;
        p.base.lispsm.n = n;
        const double m = splitOneWorstOverFine(computeCascadeSetup(view, light, streetBounds(), p), view, light, fine);
        if (m < bestFixed) {
            bestFixed = m;
            bestN = n;
        }
    }
    const double searched = splitOneWorstOverFine(withFine, view, light, fine);
    const double fromCoarse = splitOneWorstOverFine(coarseOnly, view, light, fine);
    // Measured: split 1 = 0.1-9.6 m; searched over the fine grid n 2.27 -> 8.21 (the best fixed n,
    // 2: 8.21); over the coarse grid's points in the split (what the split searched before) n 20.1
    // -> 9.31. On the street scene the coarse choice was 2.9x worse in the split's p99 (cascades.cpp).
    EXPECT_LE(searched, 1.05 * bestFixed) << "n " << withFine.splits[0].setup.diagnostics.nUsed << ", best fixed n " << bestN;
    EXPECT_GT(fromCoarse, 1.1 * searched) << "coarse n " << coarseOnly.splits[0].setup.diagnostics.nUsed;
}

}  // namespace
}  // namespace shadowlab
