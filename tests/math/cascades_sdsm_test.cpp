// Sample distribution cascades (math/cascades_sdsm.h): split depths from the samples, the k-DOP
// around a split's samples, and the cascade setup built on them (tight maps that still hold every
// sample and its casters), with the fallbacks to the practical scheme.
// Split depths balanced on the predicted footprint (math/cascades_sdsm_balance.h): a street whose
// near part fills the image and whose far part is narrow gets split depths under which the maps'
// largest unwarped footprint falls against the logarithmic partition; a view whose splits all span
// the image keeps that partition.
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

using setup_test::sunFrom;
using setup_test::terrain;

ViewFrustum sdsmStreetView() {
    ViewFrustum v = setup_test::groundView({0, -0.1, -1});
    v.zFar = 120.0;
    return v;
}

using setup_test::eyeDepth;

bool inView(const ViewFrustum& view, const glm::dvec3& p) {
    const glm::dvec4 c = view.projectionMatrix() * view.viewMatrix() * glm::dvec4(p, 1.0);
    return c.w > 0 && std::abs(c.x) < c.w && std::abs(c.y) < c.w && std::abs(c.z) < c.w;
}

// `count` points drawn by `draw(rng)`, kept where the camera sees them, as a 180-row pre-pass.
template <class Draw>
VisibleSamples visibleSamples(const ViewFrustum& view, int count, std::uint64_t seed, Draw draw) {
    Rng rng(seed);
    VisibleSamples s;
    s.pixelAngle = 2.0 * std::tan(0.5 * view.fovY) / 180.0;
    while (int(s.points.size()) < count) {
        const glm::dvec3 p = draw(rng);
        if (inView(view, p)) s.points.push_back(p);
    }
    return s;
}

// A narrow street seen down its length: ground points 6 m either side of the axis, 4-80 m ahead.
// The view frustum is 140 m wide at 80 m, so V_i n S holds far more than the visible receivers.
VisibleSamples streetSamples(const ViewFrustum& view, int count, std::uint64_t seed = 3) {
    return visibleSamples(view, count, seed,
                          [&](Rng& rng) { return glm::dvec3{rng.uniform(-6, 6), 0.0, view.eye.z - rng.uniform(4, 80)}; });
}

CascadeParams sdsmParams(SplitParameterization per, const VisibleSamples& samples) {
    CascadeParams p;
    p.splits = 4;
    p.perSplit = per;
    p.placement = SplitPlacement::Sdsm;
    p.samples = samples;
    return p;
}

void expectInClipCube(const glm::dmat4& m, const glm::dvec3& p, const std::string& what) {
    ASSERT_GT((m * glm::dvec4(p, 1.0)).w, 0.0) << what;
    const glm::dvec3 q = setup_test::ndc(m, p);
    EXPECT_LE(std::max({std::abs(q.x), std::abs(q.y), std::abs(q.z)}), 1.0 + 1e-4) << what;
}

TEST(SdsmSplits, LogarithmicOverTheSamplesDepthRange) {
    const ViewFrustum view = sdsmStreetView();
    const glm::dvec3 f = glm::normalize(view.forward);
    VisibleSamples s;
    for (double z : {3.0, 7.0, 20.0, 48.0}) s.points.push_back(view.eye + f * z);
    s.points.push_back(view.eye - f * 5.0);  // behind the eye: not a visible sample
    const std::vector<double> z = sdsmSplitDepths(s, view.eye, f, view.zNear, view.zFar, 4);
    ASSERT_EQ(z.size(), 5u);
    EXPECT_NEAR(z.front(), 3.0, 1e-9);
    EXPECT_NEAR(z.back(), 48.0, 1e-9);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(z[i + 1] / z[i], 2.0, 1e-9) << "equal far/near ratio per split";
    // Clamped to the view's range.
    const std::vector<double> clamped = sdsmSplitDepths(s, view.eye, f, view.zNear, 24.0, 2);
    ASSERT_EQ(clamped.size(), 3u);
    EXPECT_NEAR(clamped.back(), 24.0, 1e-9);
}

TEST(SdsmSplits, NoUsableSamplesGiveNoSplits) {
    const ViewFrustum view = sdsmStreetView();
    const glm::dvec3 f = glm::normalize(view.forward);
    EXPECT_TRUE(sdsmSplitDepths({}, view.eye, f, view.zNear, view.zFar, 4).empty());
    VisibleSamples one;
    one.points = {view.eye + f * 10.0, view.eye + f * 10.0};  // one depth: nothing to split
    EXPECT_TRUE(sdsmSplitDepths(one, view.eye, f, view.zNear, view.zFar, 4).empty());
    VisibleSamples bad;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    bad.points = {glm::dvec3(nan), view.eye - f};
    EXPECT_TRUE(sdsmSplitDepths(bad, view.eye, f, view.zNear, view.zFar, 4).empty());
    EXPECT_TRUE(sdsmSplitDepths(streetSamples(view, 50), view.eye, f, 1.0, 1.0, 4).empty());
}

TEST(SdsmBounds, TheKDopHoldsItsPointsAndCutsOffTheRest) {
    Rng rng(11);
    const glm::dvec3 light = glm::normalize(glm::dvec3(0.4, -1, 0.3)), forward{0, 0, -1};
    std::vector<glm::dvec3> pts;
    for (int i = 0; i < 200; ++i) pts.push_back({rng.uniform(-5, 5), rng.uniform(0, 1), rng.uniform(-40, -10)});
    const std::vector<glm::dvec4> planes = sampleBoundPlanes(pts, light, forward, 0.0);
    ASSERT_EQ(planes.size(), 20u);  // light, view and 8 directions across the light, two sides each
    auto inside = [&](const glm::dvec3& p, double tol) {
        for (const glm::dvec4& q : planes)
            if (glm::dot(glm::dvec3(q), p) + q.w > tol) return false;
        return true;
    };
    for (const glm::dvec3& p : pts) EXPECT_TRUE(inside(p, 1e-9));
    EXPECT_FALSE(inside({20, 0.5, -20}, 0.0));   // beside the samples
    EXPECT_FALSE(inside({0, 0.5, -60}, 0.0));    // beyond them along the view
    EXPECT_FALSE(inside({0, -10, -20}, 0.0));    // under them, along the light
    // A pad widens every slab by that much.
    const std::vector<glm::dvec4> padded = sampleBoundPlanes(pts, light, forward, 2.0);
    for (std::size_t i = 0; i < planes.size(); ++i) EXPECT_NEAR(padded[i].w, planes[i].w - 2.0, 1e-6);
    // Nothing usable: no planes (the caller keeps V_i n S).
    EXPECT_TRUE(sampleBoundPlanes({}, light, forward, 1.0).empty());
    EXPECT_TRUE(sampleBoundPlanes({glm::dvec3(std::numeric_limits<double>::infinity())}, light, forward, 1.0).empty());
    EXPECT_TRUE(sampleBoundPlanes(pts, glm::dvec3(0.0), forward, 1.0).empty());
}

TEST(SdsmCascades, TightSplitsHoldTheirSamplesAndCastersWithSmallerTexels) {
    const ViewFrustum view = sdsmStreetView();
    const VisibleSamples samples = streetSamples(view, 4000);
    for (const glm::dvec3 dir : {glm::dvec3(0.3, -1, 0.2), glm::dvec3(-1, -0.25, 0.1), glm::dvec3(0, -0.3, 1)})
        for (SplitParameterization per : {SplitParameterization::Ssm, SplitParameterization::Lispsm}) {
            const ShadowLight light = sunFrom(dir);
            const CascadeSetup tight = computeCascadeSetup(view, light, terrain(), sdsmParams(per, samples));
            ASSERT_TRUE(tight.error.empty()) << tight.error;
            EXPECT_EQ(tight.placement, SplitPlacement::Sdsm);
            EXPECT_TRUE(tight.placementNote.empty());
            // The practical scheme's slices V_i n S at the same split depths (placed by hand over
            // the samples' range).
            CascadeParams loose = sdsmParams(per, samples);
            loose.placement = SplitPlacement::Lambda;
            double nearest = 1e300, farthest = 0.0;
            for (const glm::dvec3& p : samples.points) {
                nearest = std::min(nearest, eyeDepth(view, p));
                farthest = std::max(farthest, eyeDepth(view, p));
            }
            loose.visibleNear = nearest;
            loose.visibleFar = farthest;
            for (std::size_t i = 0; i + 1 < tight.splits.size(); ++i)
                loose.manualSplits.push_back((tight.splits[i].zFar - nearest) / (farthest - nearest));
            const CascadeSetup wide = computeCascadeSetup(view, light, terrain(), loose);
            ASSERT_EQ(tight.splits.size(), wide.splits.size());
            int shrunk = 0;
            for (std::size_t i = 0; i < tight.splits.size(); ++i) {
                const CascadeSplit& split = tight.splits[i];
                const std::string what = std::string(splitParameterizationName(per)) + " split " + std::to_string(i);
                EXPECT_NEAR(split.zFar, wide.splits[i].zFar, 1e-9 * split.zFar) << what;
                ASSERT_TRUE(split.setup.valid) << what;
                EXPECT_TRUE(split.tightBounds) << what;
                EXPECT_GT(split.samples, 0) << what;
                const double zLow = i == 0 ? 0.0 : split.zNear;
                const double zHigh = i + 1 == tight.splits.size() ? 1e300 : split.zFar;
                for (const glm::dvec3& p : samples.points) {
                    const double z = eyeDepth(view, p);
                    if (z < zLow || z >= zHigh) continue;
                    expectInClipCube(split.setup.worldToShadowClip, p, what + ": sample");
                    // A caster 3 m toward the light from a sample still reaches the split's map.
                    Aabb caster;
                    caster.extend(p - light.direction * 3.0);
                    EXPECT_TRUE(casterCanReach(split.setup, caster)) << what;
                }
                if (split.texelWorldSize < 0.7 * wide.splits[i].texelWorldSize) ++shrunk;
            }
            EXPECT_GE(shrunk, 2) << splitParameterizationName(per) << ": the street's splits get smaller texels";
        }
}

TEST(SdsmCascades, FallsBackToLambdaAndSaysWhy) {
    const ViewFrustum view = sdsmStreetView();
    const ShadowLight light = sunFrom({0.3, -1, 0.2});
    CascadeParams lambda = sdsmParams(SplitParameterization::Ssm, {});
    lambda.placement = SplitPlacement::Lambda;
    const CascadeSetup reference = computeCascadeSetup(view, light, terrain(), lambda);
    // No samples (no pre-pass of this view).
    const CascadeSetup none = computeCascadeSetup(view, light, terrain(), sdsmParams(SplitParameterization::Ssm, {}));
    EXPECT_EQ(none.placement, SplitPlacement::Lambda);
    EXPECT_NE(none.placementNote.find("no pre-pass"), std::string::npos);
    ASSERT_EQ(none.splits.size(), reference.splits.size());
    for (std::size_t i = 0; i < none.splits.size(); ++i) {
        EXPECT_EQ(none.splits[i].setup.worldToShadowClip, reference.splits[i].setup.worldToShadowClip);
        EXPECT_FALSE(none.splits[i].tightBounds);
    }
    // Stable splits keep their view-independent bound.
    const CascadeSetup stable =
        computeCascadeSetup(view, light, terrain(), sdsmParams(SplitParameterization::StableSsm, streetSamples(view, 100)));
    EXPECT_EQ(stable.placement, SplitPlacement::Lambda);
    EXPECT_NE(stable.placementNote.find("stable"), std::string::npos);
}

TEST(SdsmCascades, ASplitWithoutSamplesKeepsItsSlice) {
    // Samples only at 10-12 m and 60 m, splits placed by hand at 15 / 25 / 35 m: the middle ones
    // hold none and keep V_i n S rather than an empty map.
    const ViewFrustum view = sdsmStreetView();
    const glm::dvec3 f = glm::normalize(view.forward);
    VisibleSamples s;
    s.pixelAngle = 0.005;
    for (double z : {10.0, 11.0, 12.0, 60.0}) {
        glm::dvec3 p = view.eye + f * z;
        p.y = 1.0;  // above the ground, inside S
        s.points.push_back(p);
    }
    CascadeParams params = sdsmParams(SplitParameterization::Ssm, s);
    params.manualSplits = {0.1, 0.3, 0.5};
    const CascadeSetup cs = computeCascadeSetup(view, sunFrom({0.3, -1, 0.2}), terrain(), params);
    ASSERT_EQ(cs.placement, SplitPlacement::Sdsm);
    int empty = 0;
    for (const CascadeSplit& split : cs.splits) {
        EXPECT_TRUE(split.setup.valid);
        if (split.samples == 0) {
            ++empty;
            EXPECT_FALSE(split.tightBounds);
        }
    }
    EXPECT_GE(empty, 1);
}

// Ground 3-80 m ahead, as wide as the view up to 12 m; beyond, a street 12 m wide between walls
// 8 m high that hide the rest.
VisibleSamples narrowingStreet(const ViewFrustum& view, int count) {
    return visibleSamples(view, count, 5, [&](Rng& rng) {
        const double ahead = rng.uniform(3, 80);
        const double x = rng.uniform(-60, 60);
        if (ahead > 12.0 && std::abs(x) > 6.0) return glm::dvec3{x > 0 ? 6.0 : -6.0, rng.uniform(0, 8), view.eye.z - ahead};
        return glm::dvec3{x, 0.0, view.eye.z - ahead};
    });
}

// Ground over the whole view 3-80 m ahead: every split spans the image's width.
VisibleSamples openGround(const ViewFrustum& view, int count) {
    return visibleSamples(view, count, 6, [&](Rng& rng) {
        const double x = rng.uniform(-120, 120);
        return glm::dvec3{x, 0.0, view.eye.z - rng.uniform(3, 80)};
    });
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
    const ViewFrustum view = sdsmStreetView();
    const VisibleSamples samples = narrowingStreet(view, 6000);
    for (const glm::dvec3 dir : {glm::dvec3(0.3, -1, 0.2), glm::dvec3(-1, -0.5, 0.1)}) {
        const ShadowLight light = sunFrom(dir);
        const CascadeSetup balanced = computeCascadeSetup(view, light, terrain(), sdsmParams(SplitParameterization::Ssm, samples));
        ASSERT_EQ(balanced.placement, SplitPlacement::Sdsm) << balanced.placementNote;
        // The logarithmic partition over the samples' range, placed by hand, same tight bounds.
        const glm::dvec3 f = glm::normalize(view.forward);
        const std::vector<double> log = sdsmSplitDepths(samples, view.eye, f, view.zNear, view.zFar, 4);
        ASSERT_EQ(log.size(), 5u);
        CascadeParams byLog = sdsmParams(SplitParameterization::Ssm, samples);
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
    const ViewFrustum view = sdsmStreetView();
    const VisibleSamples samples = openGround(view, 8000);
    const glm::dvec3 f = glm::normalize(view.forward);
    const std::vector<double> log = sdsmSplitDepths(samples, view.eye, f, view.zNear, view.zFar, 4);
    const BalancedSplits balanced = balancedSplits(samples, view.eye, f, {0, -1, 0}, view.zNear, view.zFar, 4);
    const std::vector<double>& z = balanced.depths;
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
    // Each split's prediction, from its bins, is its samples' own.
    ASSERT_EQ(balanced.predictedPerK.size(), 4u);
    for (int i = 0; i < 4; ++i) {
        const double own = predictedSplitFootprint(samples.points, view.eye, f, {0, -1, 0}, z[i], i == 3 ? 1e300 : z[i + 1]);
        EXPECT_NEAR(balanced.predictedPerK[std::size_t(i)], own, 0.01 * own) << i;
    }
    for (int i = 0; i < 4; ++i) EXPECT_NEAR((z[i + 1] / z[i]) / (log[i + 1] / log[i]), 1.0, 0.15) << i;
}

TEST(SdsmBalance, DegenerateInputGivesNoSplitsOrStillIncreasingOnes) {
    const ViewFrustum view = sdsmStreetView();
    const glm::dvec3 f = glm::normalize(view.forward), down{0, -1, 0};
    EXPECT_TRUE(balancedSplits({}, view.eye, f, down, view.zNear, view.zFar, 4).empty());
    VisibleSamples one;
    one.points = {view.eye + f * 10.0, view.eye + f * 10.0};
    EXPECT_TRUE(balancedSplits(one, view.eye, f, down, view.zNear, view.zFar, 4).empty());
    const VisibleSamples street = narrowingStreet(view, 500);
    EXPECT_TRUE(balancedSplits(street, view.eye, f, glm::dvec3(0.0), view.zNear, view.zFar, 4).empty());
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(balancedSplits(street, view.eye, f, glm::dvec3(nan), view.zNear, view.zFar, 4).empty());
    EXPECT_EQ(predictedSplitFootprint(street.points, view.eye, f, glm::dvec3(0.0), 0.0, 1e300), 0.0);
    // Two depths for four splits, a NaN point and one behind the eye: four splits all the same,
    // strictly increasing from the nearest to the farthest sample.
    VisibleSamples two;
    two.points = {view.eye + f * 10.0 + glm::dvec3(3, 0, 0), view.eye + f * 60.0, glm::dvec3(nan), view.eye - f * 5.0};
    const std::vector<double> z = balancedSplits(two, view.eye, f, down, view.zNear, view.zFar, 4).depths;
    ASSERT_EQ(z.size(), 5u);
    EXPECT_NEAR(z.front(), 10.0, 1e-9);
    EXPECT_NEAR(z.back(), 60.0, 1e-9);
    for (int i = 0; i < 4; ++i) EXPECT_LT(z[i], z[i + 1]);
    // Looking straight along the light: any axis across it serves.
    EXPECT_EQ(balancedSplits(street, view.eye, f, f, view.zNear, view.zFar, 4).depths.size(), 5u);
}

TEST(SdsmBalance, ASpotKeepsTheLogarithmicPartition) {
    const ViewFrustum view = sdsmStreetView();
    const VisibleSamples samples = narrowingStreet(view, 2000);
    ShadowLight spot;
    spot.kind = ShadowLightKind::Spot;
    spot.position = {0, 30, 10};
    spot.direction = glm::normalize(glm::dvec3(0, -1, -0.5));
    spot.outerConeAngle = 1.2;
    const CascadeSetup cs = computeCascadeSetup(view, spot, terrain(), sdsmParams(SplitParameterization::Ssm, samples));
    ASSERT_EQ(cs.placement, SplitPlacement::Sdsm);
    const std::vector<double> log =
        sdsmSplitDepths(samples, view.eye, glm::normalize(view.forward), view.zNear, view.zFar, 4);
    ASSERT_EQ(cs.splits.size(), 4u);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(cs.splits[std::size_t(i)].zFar, log[std::size_t(i) + 1], 1e-9);
    for (const CascadeSplit& s : cs.splits) EXPECT_EQ(s.predictedFootprintPerK, 0.0);
}

}  // namespace
}  // namespace shadowlab
