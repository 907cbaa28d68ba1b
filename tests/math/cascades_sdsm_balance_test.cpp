// Sample distribution split depths balanced on the predicted footprint
// (math/cascades_sdsm_balance.h): a street whose near part fills the image and whose far part is
// narrow gets split depths under which the maps' largest unwarped footprint falls
// against the logarithmic partition; a view whose splits all span the image keeps that partition.
#include "math/cascades.h"
#include "math/cascades_sdsm_balance.h"

#include "math/random.h"
#include "shadow_setup_fixtures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowlab {
namespace {

using setup_test::eyeDepth;
using setup_test::sunFrom;
using setup_test::terrain;

ViewFrustum balanceView() {
    ViewFrustum v = setup_test::groundView({0, -0.1, -1});
    v.zFar = 120.0;
    return v;
}

bool inView(const ViewFrustum& view, const glm::dvec3& p) {
    const glm::dvec4 c = view.projectionMatrix() * view.viewMatrix() * glm::dvec4(p, 1.0);
    return c.w > 0 && std::abs(c.x) < c.w && std::abs(c.y) < c.w && std::abs(c.z) < c.w;
}

// Ground 3-80 m ahead, as wide as the view up to 12 m; beyond, a street 12 m wide between walls
// 8 m high that hide the rest.
VisibleSamples narrowingStreet(const ViewFrustum& view, int count) {
    Rng rng(5);
    VisibleSamples s;
    s.pixelAngle = 2.0 * std::tan(0.5 * view.fovY) / 180.0;
    while (int(s.points.size()) < count) {
        const double ahead = rng.uniform(3, 80);
        glm::dvec3 p{rng.uniform(-60, 60), 0.0, view.eye.z - ahead};
        if (ahead > 12.0 && std::abs(p.x) > 6.0) p = {p.x > 0 ? 6.0 : -6.0, rng.uniform(0, 8), p.z};
        if (inView(view, p)) s.points.push_back(p);
    }
    return s;
}

// Ground over the whole view 3-80 m ahead: every split spans the image's width.
VisibleSamples openGround(const ViewFrustum& view, int count) {
    Rng rng(6);
    VisibleSamples s;
    s.pixelAngle = 2.0 * std::tan(0.5 * view.fovY) / 180.0;
    while (int(s.points.size()) < count) {
        const glm::dvec3 p{rng.uniform(-120, 120), 0.0, view.eye.z - rng.uniform(3, 80)};
        if (inView(view, p)) s.points.push_back(p);
    }
    return s;
}

CascadeParams sdsmParams(const VisibleSamples& samples) {
    CascadeParams p;
    p.splits = 4;
    p.perSplit = SplitParameterization::Ssm;
    p.placement = SplitPlacement::Sdsm;
    p.samples = samples;
    return p;
}

// The largest unwarped footprint over the cascade's maps, up to the constant K: texel world
// size over eye depth at each sample, in the split whose depth range holds it.
double largestTexelOverDepth(const ViewFrustum& view, const CascadeSetup& cs, const VisibleSamples& samples) {
    double worst = 0.0;
    for (const glm::dvec3& p : samples.points) {
        const double z = eyeDepth(view, p);
        std::size_t i = 0;
        while (i + 1 < cs.splits.size() && z >= cs.splits[i].zFar) ++i;
        worst = std::max(worst, texelWorldSizeAt(cs.splits[i].setup.worldToShadowClip, p, 1024) / z);
    }
    return worst;
}

TEST(SdsmBalance, ANarrowingStreetGetsASmallerWorstFootprint) {
    const ViewFrustum view = balanceView();
    const VisibleSamples samples = narrowingStreet(view, 6000);
    for (const glm::dvec3 dir : {glm::dvec3(0.3, -1, 0.2), glm::dvec3(-1, -0.5, 0.1)}) {
        const ShadowLight light = sunFrom(dir);
        const CascadeSetup balanced = computeCascadeSetup(view, light, terrain(), sdsmParams(samples));
        ASSERT_EQ(balanced.placement, SplitPlacement::Sdsm) << balanced.placementNote;
        // The logarithmic partition over the samples' range, placed by hand, same tight bounds.
        const glm::dvec3 f = glm::normalize(view.forward);
        const std::vector<double> log = sdsmSplitDepths(samples, view.eye, f, view.zNear, view.zFar, 4);
        ASSERT_EQ(log.size(), 5u);
        CascadeParams byLog = sdsmParams(samples);
        for (int i = 1; i < 4; ++i) byLog.manualSplits.push_back((log[i] - log[0]) / (log[4] - log[0]));
        const CascadeSetup logarithmic = computeCascadeSetup(view, light, terrain(), byLog);
        ASSERT_EQ(balanced.splits.size(), 4u);
        // Light from the side: the near splits are as wide as the view, the far ones long and
        // narrow; the logarithmic partition's near splits hold the worst footprint (1.91 against
        // 1.61 and 2.95 against 1.99 here).
        EXPECT_LT(largestTexelOverDepth(view, balanced, samples), 0.9 * largestTexelOverDepth(view, logarithmic, samples));
        // The prediction the split depths balanced, reported per split.
        double lo = 1e300, hi = 0.0;
        for (const CascadeSplit& s : balanced.splits) {
            EXPECT_GT(s.predictedFootprintPerK, 0.0);
            lo = std::min(lo, s.predictedFootprintPerK);
            hi = std::max(hi, s.predictedFootprintPerK);
        }
        EXPECT_LT(hi, 1.5 * lo) << "the splits' predicted footprints are balanced";
    }
}

TEST(SdsmBalance, SplitsSpanningTheWholeImageKeepTheLogarithmicRatios) {
    // Light straight down: a split's light-space extent is the view's width at its far end, so
    // its predicted footprint is proportional to z_far / z_near, equal for every split at the
    // logarithmic partition.
    const ViewFrustum view = balanceView();
    const VisibleSamples samples = openGround(view, 8000);
    const glm::dvec3 f = glm::normalize(view.forward);
    const std::vector<double> log = sdsmSplitDepths(samples, view.eye, f, view.zNear, view.zFar, 4);
    const std::vector<double> z = balancedSplitDepths(samples, view.eye, f, {0, -1, 0}, view.zNear, view.zFar, 4);
    ASSERT_EQ(log.size(), 5u);
    ASSERT_EQ(z.size(), 5u);
    EXPECT_DOUBLE_EQ(z.front(), log.front());
    EXPECT_DOUBLE_EQ(z.back(), log.back());
    // The same ratios up to the samples' scatter (the widest sample of a split is not exactly at
    // its far corners), and no worse a largest prediction than the logarithmic partition's but
    // for the bins' resolution.
    const double bin = std::exp(std::log(log.back() / log.front()) / kBalanceBins);
    auto largest = [&](const std::vector<double>& depths) {
        double worst = 0.0;
        for (int i = 0; i < 4; ++i)
            worst = std::max(worst, predictedSplitFootprint(samples.points, view.eye, f, {0, -1, 0}, depths[i],
                                                            i == 3 ? 1e300 : depths[i + 1]));
        return worst;
    };
    EXPECT_LE(largest(z), largest(log) * bin);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR((z[i + 1] / z[i]) / (log[i + 1] / log[i]), 1.0, 0.15) << i;
}

TEST(SdsmBalance, DegenerateInputGivesNoSplitsOrStillIncreasingOnes) {
    const ViewFrustum view = balanceView();
    const glm::dvec3 f = glm::normalize(view.forward), down{0, -1, 0};
    EXPECT_TRUE(balancedSplitDepths({}, view.eye, f, down, view.zNear, view.zFar, 4).empty());
    VisibleSamples one;
    one.points = {view.eye + f * 10.0, view.eye + f * 10.0};
    EXPECT_TRUE(balancedSplitDepths(one, view.eye, f, down, view.zNear, view.zFar, 4).empty());
    const VisibleSamples street = narrowingStreet(view, 500);
    EXPECT_TRUE(balancedSplitDepths(street, view.eye, f, glm::dvec3(0.0), view.zNear, view.zFar, 4).empty());
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(balancedSplitDepths(street, view.eye, f, glm::dvec3(nan), view.zNear, view.zFar, 4).empty());
    EXPECT_EQ(predictedSplitFootprint(street.points, view.eye, f, glm::dvec3(0.0), 0.0, 1e300), 0.0);
    // Two depths for four splits, a NaN point and one behind the eye: four splits all the same,
    // strictly increasing from the nearest to the farthest sample.
    VisibleSamples two;
    two.points = {view.eye + f * 10.0 + glm::dvec3(3, 0, 0), view.eye + f * 60.0, glm::dvec3(nan), view.eye - f * 5.0};
    const std::vector<double> z = balancedSplitDepths(two, view.eye, f, down, view.zNear, view.zFar, 4);
    ASSERT_EQ(z.size(), 5u);
    EXPECT_NEAR(z.front(), 10.0, 1e-9);
    EXPECT_NEAR(z.back(), 60.0, 1e-9);
    for (int i = 0; i < 4; ++i) EXPECT_LT(z[i], z[i + 1]);
    // Looking straight along the light: any axis across it serves.
    EXPECT_EQ(balancedSplitDepths(street, view.eye, f, f, view.zNear, view.zFar, 4).size(), 5u);
}

TEST(SdsmBalance, ASpotKeepsTheLogarithmicPartition) {
    const ViewFrustum view = balanceView();
    const VisibleSamples samples = narrowingStreet(view, 2000);
    ShadowLight spot;
    spot.kind = ShadowLightKind::Spot;
    spot.position = {0, 30, 10};
    spot.direction = glm::normalize(glm::dvec3(0, -1, -0.5));
    spot.outerConeAngle = 1.2;
    const CascadeSetup cs = computeCascadeSetup(view, spot, terrain(), sdsmParams(samples));
    ASSERT_EQ(cs.placement, SplitPlacement::Sdsm);
    const std::vector<double> log =
        sdsmSplitDepths(samples, view.eye, glm::normalize(view.forward), view.zNear, view.zFar, 4);
    ASSERT_EQ(cs.splits.size(), 4u);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(cs.splits[std::size_t(i)].zFar, log[std::size_t(i) + 1], 1e-9);
    for (const CascadeSplit& s : cs.splits) EXPECT_EQ(s.predictedFootprintPerK, 0.0);
}

}  // namespace
}  // namespace shadowlab
