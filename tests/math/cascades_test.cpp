// Cascaded shadow maps (math/cascades.h): split positions against the closed forms, per-split B_i
// and containment, and the stable SSM's world-fixed texel grid.
#include "math/cascades.h"

#include "math/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace shadowlab {
namespace {

const SplitParameterization kAllPerSplit[] = {SplitParameterization::Ssm, SplitParameterization::StableSsm,
                                              SplitParameterization::Lispsm};

Aabb cascadeTerrain() {
    Aabb b;
    b.min = {-100, 0, -100};
    b.max = {100, 30, 100};
    return b;
}

ViewFrustum cascadeView(glm::dvec3 eye = {0, 2, 50}, glm::dvec3 forward = {0, -0.1, -1}) {
    ViewFrustum v;
    v.eye = eye;
    v.forward = glm::normalize(forward);
    v.fovY = 60.0 * std::numbers::pi / 180.0;
    v.aspect = 1.5;
    v.zNear = 0.5;
    v.zFar = 120.0;
    return v;
}

ShadowLight sun(glm::dvec3 travel) {
    ShadowLight l;
    l.direction = glm::normalize(travel);
    return l;
}

CascadeParams cascade(SplitParameterization perSplit, int splits = 4, double lambda = 0.5) {
    CascadeParams p;
    p.splits = splits;
    p.lambda = lambda;
    p.perSplit = perSplit;
    p.mapResolution = 1024;
    return p;
}

// Random points of a convex body (convex combinations of its vertices, skewed toward corners).
std::vector<glm::dvec3> samplePoints(const ConvexBody& body, Rng& rng, int count) {
    const auto verts = body.vertices();
    std::vector<glm::dvec3> out;
    for (int i = 0; i < count; ++i) {
        glm::dvec3 p{0.0};
        double w = 0.0;
        for (const auto& q : verts) {
            const double a = std::pow(rng.uniform(), 4.0);
            p += a * q;
            w += a;
        }
        out.push_back(p / w);
    }
    return out;
}

void expectInClipCube(const glm::dmat4& m, const glm::dvec3& p, const char* what) {
    const glm::dvec4 h = m * glm::dvec4(p, 1.0);
    ASSERT_GT(h.w, 0.0) << what;
    EXPECT_LE(std::abs(h.x / h.w), 1.0 + 1e-4) << what;
    EXPECT_LE(std::abs(h.y / h.w), 1.0 + 1e-4) << what;
    EXPECT_LE(std::abs(h.z / h.w), 1.0 + 1e-4) << what;
}

// --- Split positions ---------------------------------------------------------------------------

TEST(CascadeSplits, LambdaZeroIsUniform) {
    const auto z = practicalSplitDepths(1.0, 1000.0, 3, 0.0);
    ASSERT_EQ(z.size(), 4u);
    EXPECT_DOUBLE_EQ(z[0], 1.0);
    EXPECT_NEAR(z[1], 334.0, 1e-9);
    EXPECT_NEAR(z[2], 667.0, 1e-9);
    EXPECT_DOUBLE_EQ(z[3], 1000.0);
}

TEST(CascadeSplits, LambdaOneIsLogarithmic) {
    const auto z = practicalSplitDepths(1.0, 1000.0, 3, 1.0);
    ASSERT_EQ(z.size(), 4u);
    EXPECT_NEAR(z[1], 10.0, 1e-9);
    EXPECT_NEAR(z[2], 100.0, 1e-9);
    // Every split spans the same far/near ratio: the log scheme's equal perspective aliasing.
    const auto z4 = practicalSplitDepths(0.1, 100.0, 4, 1.0);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(z4[i + 1] / z4[i], std::pow(1000.0, 0.25), 1e-9);
}

TEST(CascadeSplits, LambdaHalfAveragesTheTwo) {
    const auto z = practicalSplitDepths(1.0, 1000.0, 3, 0.5);
    EXPECT_NEAR(z[1], 0.5 * (10.0 + 334.0), 1e-9);
    EXPECT_NEAR(z[2], 0.5 * (100.0 + 667.0), 1e-9);
    EXPECT_DOUBLE_EQ(z[3], 1000.0);
}

TEST(CascadeSplits, ManualPositionsAreFractionsOfTheRange) {
    CascadeParams p = cascade(SplitParameterization::Ssm, 3);
    p.manualSplits = {0.1, 0.4};
    const auto z = cascadeSplitDepths(p, 2.0, 102.0);
    ASSERT_EQ(z.size(), 4u);
    EXPECT_DOUBLE_EQ(z[1], 12.0);
    EXPECT_DOUBLE_EQ(z[2], 42.0);
}

TEST(CascadeSplits, BadParamsGiveAMessageAndNoSplits) {
    CascadeParams p = cascade(SplitParameterization::Ssm, 5);
    EXPECT_NE(validateCascadeParams(p).find("csm.splits"), std::string::npos);
    p.splits = 2;
    p.lambda = 1.5;
    EXPECT_NE(validateCascadeParams(p).find("csm.lambda"), std::string::npos);
    p.lambda = 0.5;
    p.manualSplits = {0.5, 0.6};
    EXPECT_NE(validateCascadeParams(p).find("splits - 1"), std::string::npos);
    p.splits = 3;
    p.manualSplits = {0.6, 0.5};
    EXPECT_NE(validateCascadeParams(p).find("increasing"), std::string::npos);
    p.manualSplits = {0.2, std::nan("")};
    EXPECT_FALSE(validateCascadeParams(p).empty());
    const CascadeSetup s = computeCascadeSetup(cascadeView(), sun({1, -1, 0}), cascadeTerrain(), p);
    EXPECT_FALSE(s.error.empty());
    EXPECT_TRUE(s.splits.empty());
    p.manualSplits = {0.2, 0.5};
    EXPECT_TRUE(validateCascadeParams(p).empty());
}

// --- Per-split B_i and containment -------------------------------------------------------------

TEST(CascadeSetups, EachSplitsBodyHoldsItsVisiblePartAndMapsIntoTheClipCube) {
    Rng rng(7);
    const glm::dvec3 lights[] = {{0.3, -1, 0.2}, {-1, -0.05, 0.1}, {0, -1, 0}, {0, -0.2, -1}, {0, -0.2, 1}};
    for (const auto& dir : lights)
        for (SplitParameterization per : kAllPerSplit) {
            const ViewFrustum view = cascadeView();
            const ShadowLight light = sun(dir);
            const CascadeSetup cs = computeCascadeSetup(view, light, cascadeTerrain(), cascade(per));
            ASSERT_TRUE(cs.error.empty()) << cs.error;
            ASSERT_EQ(cs.splits.size(), 4u);
            for (const CascadeSplit& split : cs.splits) {
                SCOPED_TRACE(std::string(splitParameterizationName(per)) + " split near " +
                             std::to_string(split.zNear));
                ConvexBody visible;
                intersectionBody(splitFrustum(view, split.zNear, split.zFar), light, cascadeTerrain(), &visible);
                ASSERT_TRUE(split.setup.valid);
                const ConvexBody B(split.setup.diagnostics.bodyB);
                for (const auto& p : B.vertices()) expectInClipCube(split.setup.worldToShadowClip, p, "vertex of B_i");
                for (const auto& p : samplePoints(visible, rng, 50)) {
                    EXPECT_TRUE(B.contains(p, 1e-9)) << "point of V_i n S outside B_i";
                    // The split's own caster culling keeps a tiny box at any point of its B_i.
                    Aabb tiny;
                    tiny.extend(p);
                    EXPECT_TRUE(casterCanReach(split.setup, tiny));
                }
                EXPECT_GT(split.texelWorldSize, 0.0);
            }
        }
}

TEST(CascadeSetups, ContainmentHoldsFarFromTheOrigin) {
    const glm::dvec3 offset{1e5, 0, -1e5};
    Aabb scene = cascadeTerrain();
    scene.min += offset;
    scene.max += offset;
    const ViewFrustum view = cascadeView(glm::dvec3(0, 2, 50) + offset);
    for (SplitParameterization per : kAllPerSplit) {
        const CascadeSetup cs = computeCascadeSetup(view, sun({0.4, -1, 0.3}), scene, cascade(per));
        for (const CascadeSplit& split : cs.splits) {
            ASSERT_TRUE(split.setup.valid);
            for (const auto& p : ConvexBody(split.setup.diagnostics.bodyB).vertices())
                expectInClipCube(split.setup.worldToShadowClip, p, splitParameterizationName(per));
        }
    }
}

TEST(CascadeSetups, OneSsmSplitIsTheSingleFocusedMap) {
    const ViewFrustum view = cascadeView();
    const ShadowLight light = sun({0.3, -1, 0.2});
    const CascadeSetup cs = computeCascadeSetup(view, light, cascadeTerrain(), cascade(SplitParameterization::Ssm, 1));
    ShadowParams p;
    p.method = ShadowMethod::SsmFocused;
    const ShadowSetup single = computeShadowSetup(view, light, cascadeTerrain(), p);
    ASSERT_EQ(cs.splits.size(), 1u);
    EXPECT_EQ(cs.splits[0].setup.worldToShadowClip, single.worldToShadowClip);
}

TEST(CascadeSetups, LaterSplitsHaveLargerTexels) {
    // Splitting's point: the near split's texels are much smaller than one map's over the view.
    const CascadeSetup cs =
        computeCascadeSetup(cascadeView(), sun({0.3, -1, 0.2}), cascadeTerrain(), cascade(SplitParameterization::Ssm));
    ShadowParams p;
    p.method = ShadowMethod::SsmFocused;
    const ShadowSetup single = computeShadowSetup(cascadeView(), sun({0.3, -1, 0.2}), cascadeTerrain(), p);
    const double singleTexel = texelWorldSizeAt(single.worldToShadowClip, {0, 0, 0}, 2048);
    EXPECT_LT(cs.splits[0].texelWorldSize * 2.0, singleTexel) << "4 x 1024^2 against 2048^2: equal memory";
    for (int i = 1; i < 4; ++i) EXPECT_GT(cs.splits[i].texelWorldSize, cs.splits[i - 1].texelWorldSize);
}

// The stress suite's containment check (math/stress.h) for every split: random views with fov
// 10..120 deg, near 1e-3..1, far/near up to 1e5, world offsets up to 1e5, suns from any direction
// (a third exactly along the view axis or an axis), visible ranges inside the frustum or none. Every
// valid split's matrix is finite and maps the vertices of its own B_i (recomputed here from V_i)
// into the clip cube within 1e-4; a split that sees something lit is valid.
TEST(CascadeStress, EverySplitMatrixContainsItsBodyOnRandomViews) {
    Rng rng(2026);
    int checkedSplits = 0, failures = 0;
    std::string first;
    for (int trial = 0; trial < 300; ++trial) {
        const glm::dvec3 offset = rng.chance(0.3) ? glm::dvec3(0.0) : rng.unit() * rng.logUniform(1.0, 1e5);
        Aabb scene;
        const glm::dvec3 half{rng.logUniform(1.0, 2e3), rng.logUniform(0.1, 100.0), rng.logUniform(1.0, 2e3)};
        scene.min = offset - half;
        scene.max = offset + half;
        ViewFrustum view;
        view.eye = offset + glm::dvec3(rng.uniform(-1, 1) * half.x, rng.uniform(0, 1.5) * half.y, rng.uniform(-1, 1) * half.z);
        view.forward = glm::normalize(glm::dvec3(rng.uniform(-1, 1), rng.uniform(-0.8, 0.2), rng.uniform(-1, 1)));
        view.fovY = rng.uniform(10.0, 120.0) * std::numbers::pi / 180.0;
        view.aspect = rng.uniform(0.5, 2.5);
        view.zNear = rng.logUniform(1e-3, 1.0);
        view.zFar = view.zNear * rng.logUniform(10.0, 1e5);
        glm::dvec3 dir = rng.unit();
        if (trial % 3 == 0) dir = trial % 2 ? view.forward : glm::dvec3(0, -1, 0);
        if (dir.y > 0.0 && trial % 3 != 0) dir.y = -dir.y;
        const ShadowLight light = sun(dir);
        for (SplitParameterization per : kAllPerSplit) {
            CascadeParams p = cascade(per, 1 + trial % 4, rng.uniform());
            if (rng.chance(0.5)) {
                p.visibleNear = view.zNear * rng.logUniform(1.0, 100.0);
                p.visibleFar = std::min(view.zFar, p.visibleNear * rng.logUniform(2.0, 1e4));
            }
            const CascadeSetup cs = computeCascadeSetup(view, light, scene, p);
            ASSERT_TRUE(cs.error.empty()) << cs.error;
            for (const CascadeSplit& split : cs.splits) {
                const ConvexBody B = intersectionBody(splitFrustum(view, split.zNear, split.zFar), light, scene);
                if (B.empty()) continue;
                ++checkedSplits;
                const glm::dmat4& m = split.setup.worldToShadowClip;
                bool ok = split.setup.valid;
                for (int a = 0; a < 4; ++a)
                    for (int b = 0; b < 4; ++b) ok &= std::isfinite(m[a][b]);
                for (const auto& v : B.vertices()) {
                    const glm::dvec4 h = m * glm::dvec4(v, 1.0);
                    ok &= h.w > 0.0 && std::abs(h.x / h.w) <= 1.0 + 1e-4 && std::abs(h.y / h.w) <= 1.0 + 1e-4 &&
                          std::abs(h.z / h.w) <= 1.0 + 1e-4;
                }
                if (!ok && failures++ == 0)
                    first = "trial " + std::to_string(trial) + " " + splitParameterizationName(per) + " split near " +
                            std::to_string(split.zNear);
            }
        }
    }
    EXPECT_EQ(failures, 0) << "first: " << first;
    EXPECT_GT(checkedSplits, 1000);
}

// --- The visible depth range and the measured receivers (depth pre-pass) ---------------------

TEST(CascadeVisibleRange, SplitsCoverTheVisibleRangeAndTheFirstStartsAtTheNearPlane) {
    const ViewFrustum view = cascadeView();  // near 0.5, far 120
    CascadeParams p = cascade(SplitParameterization::Ssm);
    p.visibleNear = 2.0;
    p.visibleFar = 40.0;
    const CascadeDepthRange r = cascadeDepthRange(view, p);
    EXPECT_EQ(r.zNear, 2.0);
    EXPECT_EQ(r.zFar, 40.0);
    const CascadeSetup cs = computeCascadeSetup(view, sun({0.3, -1, 0.2}), cascadeTerrain(), p);
    ASSERT_EQ(cs.splits.size(), 4u);
    const auto z = practicalSplitDepths(2.0, 40.0, 4, 0.5);
    EXPECT_EQ(cs.splits[0].zNear, view.zNear) << "geometry nearer than the measured range still has a map";
    for (int i = 0; i < 4; ++i) EXPECT_DOUBLE_EQ(cs.splits[i].zFar, z[i + 1]);
    // Unknown or unusable ranges keep the view's.
    for (auto [lo, hi] : {std::pair{-1.0, -1.0}, {5.0, 5.0}, {8.0, 2.0}, {0.0, 30.0}}) {
        p.visibleNear = lo;
        p.visibleFar = hi;
        const CascadeDepthRange v = cascadeDepthRange(view, p);
        EXPECT_EQ(v.zNear, view.zNear) << lo << " " << hi;
        EXPECT_EQ(v.zFar, view.zFar) << lo << " " << hi;
    }
    p.visibleNear = 0.01;  // beyond the frustum: clamped to it
    p.visibleFar = 1e4;
    EXPECT_EQ(cascadeDepthRange(view, p).zNear, view.zNear);
    EXPECT_EQ(cascadeDepthRange(view, p).zFar, view.zFar);
}

TEST(CascadeVisibleRange, StableSplitsKeepTheNearPlaneAndSnapTheFarEndOutwards) {
    const ViewFrustum view = cascadeView();
    CascadeParams p = cascade(SplitParameterization::StableSsm);
    int changes = 0;
    CascadeDepthRange last{};
    for (int i = 0; i < 100; ++i) {
        // The visible range drifting by 0.1 % per frame, as under 1-pixel camera steps.
        p.visibleNear = 2.0 * (1.0 + 1e-3 * i);
        p.visibleFar = 40.0 * (1.0 - 1e-3 * i);
        const CascadeDepthRange r = cascadeDepthRange(view, p);
        EXPECT_EQ(r.zNear, view.zNear) << "the nearest visible pixel does not move stable splits";
        EXPECT_GE(r.zFar, p.visibleFar);
        EXPECT_LT(r.zFar, p.visibleFar * kStableDepthStep * (1 + 1e-12)) << "at most one step wider";
        const double steps = std::log(r.zFar) / std::log(kStableDepthStep);
        EXPECT_NEAR(steps, std::round(steps), 1e-9);
        if (i > 0 && (r.zNear != last.zNear || r.zFar != last.zFar)) ++changes;
        last = r;
    }
    EXPECT_LE(changes, 1) << "a 10 % drift crosses at most one step";
    // A far end that is a step already stays there (no round-off to the next one).
    p.visibleFar = std::pow(kStableDepthStep, 20);
    EXPECT_NEAR(cascadeDepthRange(view, p).zFar, p.visibleFar, 1e-9 * p.visibleFar);
    // Focused splits follow the measured range exactly (the control).
    p.perSplit = SplitParameterization::Ssm;
    EXPECT_EQ(cascadeDepthRange(view, p).zFar, p.visibleFar);
    EXPECT_EQ(cascadeDepthRange(view, p).zNear, p.visibleNear);
}

TEST(CascadeVisibleRange, EachLispsmSplitSearchesOnlyTheReceiversOfItsRange) {
    const ViewFrustum view = cascadeView();
    const ShadowLight light = sun({0.3, -1, 0.2});
    CascadeParams p = cascade(SplitParameterization::Lispsm);
    p.visibleNear = 2.0;
    p.visibleFar = 60.0;
    // Ground points straight ahead at depths 3 .. 57, normals up (lit, not grazing).
    for (double z = 3.0; z < 58.0; z += 2.0) {
        const glm::dvec3 ahead = view.eye + view.forward * z;
        p.base.receiverPoints.push_back({{ahead.x, 0.0, ahead.z}, {0, 1, 0}});
    }
    const CascadeSetup cs = computeCascadeSetup(view, light, cascadeTerrain(), p);
    ASSERT_EQ(cs.splits.size(), 4u);
    std::size_t total = 0;
    for (std::size_t i = 0; i < cs.splits.size(); ++i) {
        const double lo = i == 0 ? 0.0 : cs.splits[i].zNear, hi = i == 3 ? 1e30 : cs.splits[i].zFar;
        int expected = 0;
        for (const SurfacePoint& r : p.base.receiverPoints) {
            const double z = glm::dot(r.point - view.eye, view.forward);
            expected += z >= lo && z < hi;
        }
        ASSERT_GT(expected, 0) << "split " << i;
        EXPECT_EQ(cs.splits[i].setup.diagnostics.warpSamples, expected) << "split " << i;
        total += std::size_t(expected);
    }
    EXPECT_EQ(total, p.base.receiverPoints.size()) << "every receiver belongs to exactly one split";
}

TEST(StableSsm, DepthRowStaysPutUnderSmallCameraMoves) {
    // The depth range is snapped to whole steps of the bound: 1 cm camera steps leave the whole
    // matrix unchanged in nearly every frame (fitted every frame, it changed in every one).
    const ShadowLight light = sun({0.35, -1, 0.25});
    const ViewFrustum reference = cascadeView();
    CascadeSetup last = computeCascadeSetup(reference, light, cascadeTerrain(), cascade(SplitParameterization::StableSsm));
    int changed = 0, compared = 0;
    for (int step = 1; step <= 50; ++step) {
        ViewFrustum moved = reference;
        moved.eye.x += 0.01 * step;
        const CascadeSetup cs = computeCascadeSetup(moved, light, cascadeTerrain(), cascade(SplitParameterization::StableSsm));
        for (int i = 0; i < 4; ++i) {
            ++compared;
            const glm::dmat4& a = cs.splits[i].setup.worldToShadowClip;
            const glm::dmat4& b = last.splits[i].setup.worldToShadowClip;
            changed += a[0][2] != b[0][2] || a[1][2] != b[1][2] || a[2][2] != b[2][2] || a[3][2] != b[3][2];
        }
        last = cs;
    }
    EXPECT_LE(changed, compared / 10) << changed << " of " << compared << " depth rows changed";
}

// --- Stable SSM ----------------------------------------------------------------------------------

TEST(StableSsm, FrustumSphereHoldsTheSliceCorners) {
    for (double fov : {0.2, 1.0, 2.0})
        for (double aspect : {0.5, 1.0, 2.5}) {
            const FrustumSphere s = frustumSliceSphere(fov, aspect, 2.0, 30.0);
            const double k = std::tan(0.5 * fov) * std::sqrt(1 + aspect * aspect);
            const double dNear = std::hypot(s.centerDistance - 2.0, 2.0 * k);
            const double dFar = std::hypot(30.0 - s.centerDistance, 30.0 * k);
            EXPECT_LE(dNear, s.radius * (1 + 1e-12));
            EXPECT_LE(dFar, s.radius * (1 + 1e-12));
            // Smallest: it touches the far corners (and the near ones unless clamped to f).
            EXPECT_NEAR(dFar, s.radius, 1e-9 * s.radius);
        }
}

// The texel coordinate of a world point along the map's x and y.
glm::dvec2 texelCoordinate(const glm::dmat4& m, const glm::dvec3& p, int res) {
    const glm::dvec4 h = m * glm::dvec4(p, 1.0);
    return (glm::dvec2(h) / h.w * 0.5 + 0.5) * double(res);
}

double distanceToWholeNumber(double t) { return std::abs(t - std::round(t)); }

TEST(StableSsm, TexelGridStaysFixedUnderCameraTranslationAndRotation) {
    const ShadowLight light = sun({0.35, -1, 0.25});
    const int res = 1024;
    const ViewFrustum reference = cascadeView();
    const CascadeSetup ref = computeCascadeSetup(reference, light, cascadeTerrain(), cascade(SplitParameterization::StableSsm));
    const glm::dvec3 probes[] = {{0, 0, 0}, {13.7, 1.2, -20.3}, {-40.1, 5.5, 3.3}};
    Rng rng(99);
    int compared = 0;
    for (int trial = 0; trial < 100; ++trial) {
        ViewFrustum moved = reference;
        moved.eye += glm::dvec3(rng.uniform(-30, 30), rng.uniform(0, 10), rng.uniform(-30, 30));
        if (trial % 2 == 1) {
            const glm::dvec3 u = rng.unit();
            moved.forward = glm::normalize(glm::dvec3(u.x, -0.1 - 0.3 * std::abs(u.y), u.z));
        }
        const CascadeSetup cs = computeCascadeSetup(moved, light, cascadeTerrain(), cascade(SplitParameterization::StableSsm));
        for (int i = 0; i < 4; ++i) {
            if (!cs.splits[i].setup.valid) continue;  // a split that sees nothing of the scene
            ++compared;
            ASSERT_TRUE(cs.splits[i].setup.diagnostics.fallback.empty()) << cs.splits[i].setup.diagnostics.fallback;
            for (const auto& p : probes) {
                const glm::dvec2 d = texelCoordinate(cs.splits[i].setup.worldToShadowClip, p, res) -
                                     texelCoordinate(ref.splits[i].setup.worldToShadowClip, p, res);
                EXPECT_LT(distanceToWholeNumber(d.x), 1e-6) << "trial " << trial << " split " << i;
                EXPECT_LT(distanceToWholeNumber(d.y), 1e-6) << "trial " << trial << " split " << i;
            }
            // The texel size does not change either (so the grid is the same, not merely aligned).
            EXPECT_NEAR(cs.splits[i].setup.worldToShadowClip[0][0], ref.splits[i].setup.worldToShadowClip[0][0],
                        1e-15);
        }
    }
    EXPECT_GT(compared, 300) << "most splits of the 100 views see the scene";
}

TEST(StableSsm, FocusedSsmGridDoesMoveUnderTranslation) {
    // The control: without the stable fit the grid crawls, so the test above can fail.
    const ShadowLight light = sun({0.35, -1, 0.25});
    const ViewFrustum a = cascadeView();
    ViewFrustum b = a;
    b.eye += glm::dvec3(0.37, 0.0, -0.11);
    const CascadeSetup sa = computeCascadeSetup(a, light, cascadeTerrain(), cascade(SplitParameterization::Ssm));
    const CascadeSetup sb = computeCascadeSetup(b, light, cascadeTerrain(), cascade(SplitParameterization::Ssm));
    const glm::dvec2 d = texelCoordinate(sb.splits[1].setup.worldToShadowClip, {0, 0, 0}, 1024) -
                         texelCoordinate(sa.splits[1].setup.worldToShadowClip, {0, 0, 0}, 1024);
    EXPECT_GT(std::max(distanceToWholeNumber(d.x), distanceToWholeNumber(d.y)), 1e-3);
}

TEST(StableSsm, SpotLightFallsBackToFocusedSsmAndSaysSo) {
    ShadowLight spot;
    spot.kind = ShadowLightKind::Spot;
    spot.position = {0, 25, 20};
    spot.direction = {0, -1, -0.3};
    spot.outerConeAngle = 0.6;
    ShadowParams p;
    const ShadowSetup s = computeStableSsmSetup(cascadeView(), spot, cascadeTerrain(), p, 1024);
    ASSERT_TRUE(s.valid);
    EXPECT_NE(s.diagnostics.fallback.find("directional"), std::string::npos);
    for (const auto& v : ConvexBody(s.diagnostics.bodyB).vertices()) expectInClipCube(s.worldToShadowClip, v, "spot");
}

}  // namespace
}  // namespace shadowlab
