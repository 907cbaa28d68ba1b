// B, SSM, PSM and LiSPSM: named geometric cases and the invariants every method must keep.
#include "math/shadow_setup.h"
#include "shadow_setup_fixtures.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace shadowlab {
namespace {

using namespace setup_test;  // shadow_setup_fixtures.h


TEST(ViewFrustum, MatricesFollowGlConventions) {
    const ViewFrustum v = groundView(glm::dvec3(0.3, -0.2, -1.0));
    const glm::dmat4 refView = glm::lookAt(v.eye, v.eye + v.forward, v.up);
    const glm::dmat4 refProj = glm::perspectiveRH_NO(v.fovY, v.aspect, v.zNear, v.zFar);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            EXPECT_NEAR(v.viewMatrix()[c][r], refView[c][r], 1e-12);
            EXPECT_NEAR(v.projectionMatrix()[c][r], refProj[c][r], 1e-12);
        }
    // The near plane centre maps to NDC z = -1, the far one to +1.
    const glm::dmat4 vp = v.projectionMatrix() * v.viewMatrix();
    EXPECT_NEAR(ndc(vp, v.eye + glm::normalize(v.forward) * v.zNear).z, -1.0, 1e-12);
    EXPECT_NEAR(ndc(vp, v.eye + glm::normalize(v.forward) * v.zFar).z, 1.0, 1e-9);
    EXPECT_GT(frustumBody(v).volume(), 0.0);
}

// --- The intersection body B (thesis eq. 4.2) --------------------------------------------------

TEST(IntersectionBody, LightStraightDownReachesTheSceneTop) {
    const ViewFrustum v = groundView();
    const ShadowLight l = sunFrom({0, -1, 0});
    ConvexBody vs;
    const ConvexBody B = intersectionBody(v, l, terrain(), &vs);
    ASSERT_FALSE(B.empty());
    // B is V n S extruded straight up to the top of S: same x/z footprint, y up to 30.
    const Aabb bb = B.bounds(), vb = vs.bounds();
    EXPECT_NEAR(bb.max.y, 30.0, 1e-9);
    EXPECT_NEAR(bb.min.y, vb.min.y, 1e-9);
    EXPECT_NEAR(bb.min.x, vb.min.x, 1e-9);
    EXPECT_NEAR(bb.max.x, vb.max.x, 1e-9);
    EXPECT_NEAR(bb.min.z, vb.min.z, 1e-9);
    EXPECT_NEAR(bb.max.z, vb.max.z, 1e-9);
    expectVisiblePartInB(v, l, terrain());
    // A point above the visible ground (a potential caster) is in B; one beside the view is not.
    EXPECT_TRUE(B.contains({0, 25, 20}, 1e-9));
    EXPECT_FALSE(B.contains({90, 25, 20}, 1e-9));
}

TEST(IntersectionBody, GrazingLightStretchesAcrossTheScene) {
    const ViewFrustum v = groundView();
    const double el = glm::radians(0.5);
    const ShadowLight l = sunFrom({-std::cos(el), -std::sin(el), 0});  // from +x, nearly horizontal
    const ConvexBody B = intersectionBody(v, l, terrain());
    ASSERT_FALSE(B.empty());
    EXPECT_NEAR(B.bounds().max.x, 100.0, 1e-9) << "extruded toward the light up to the scene bounds";
    expectVisiblePartInB(v, l, terrain());
}

TEST(IntersectionBody, LightFromBehindIncludesCastersBehindTheCamera) {
    const ViewFrustum v = groundView();
    const ShadowLight l = sunFrom({0, -0.5, -1});  // travels along the view: from behind
    const ConvexBody B = intersectionBody(v, l, terrain());
    ASSERT_FALSE(B.empty());
    EXPECT_TRUE(B.contains({0, 10, 60}, 1e-9)) << "above and behind the eye, between the sun and the view";
    EXPECT_NEAR(B.bounds().max.z, 100.0, 1e-9);
    expectVisiblePartInB(v, l, terrain());
}

TEST(IntersectionBody, SpotLightIsClippedByItsCone) {
    const ViewFrustum v = groundView();
    ShadowLight l;
    l.kind = ShadowLightKind::Spot;
    l.position = {0, 20, 20};
    l.direction = {0, -1, 0};
    l.outerConeAngle = glm::radians(30.0);
    ConvexBody lvs;
    const ConvexBody B = intersectionBody(v, l, terrain(), &lvs);
    ASSERT_FALSE(B.empty());
    // Everything in B lies inside the square pyramid around the 30 degree cone.
    for (const auto& p : B.vertices()) {
        const glm::dvec3 d = p - l.position;
        EXPECT_GE(-d.y, 0.0);
        EXPECT_LE(std::abs(d.x), std::tan(glm::radians(30.0)) * -d.y + 1e-9);
        EXPECT_LE(std::abs(d.z), std::tan(glm::radians(30.0)) * -d.y + 1e-9);
    }
    EXPECT_TRUE(B.contains({0, 10, 20}, 1e-9)) << "between the light and the lit ground";
}

TEST(IntersectionBody, SpotPointingAwayGivesAnInvalidSetup) {
    const ViewFrustum v = groundView();
    ShadowLight l;
    l.kind = ShadowLightKind::Spot;
    l.position = {0, 20, 60};
    l.direction = {0, 0, 1};  // away from everything the camera sees
    l.outerConeAngle = glm::radians(20.0);
    for (ShadowMethod m : kAllMethods) {
        const ShadowSetup s = setupFor(v, l, terrain(), m);
        EXPECT_FALSE(s.valid);
        EXPECT_FALSE(s.diagnostics.fallback.empty());
        EXPECT_FALSE(casterCanReach(s, terrain()));
    }
}

// --- Invariants for all methods ------------------------------------------------------------------

struct Config {
    const char* name;
    ViewFrustum view;
    ShadowLight light;
};

std::vector<Config> configs() {
    std::vector<Config> c;
    c.push_back({"sun side", groundView(), sunFrom({1, -1, 0.2})});
    c.push_back({"sun front", groundView(), sunFrom({0, -0.4, 1})});
    c.push_back({"sun behind", groundView(), sunFrom({0, -0.4, -1})});
    c.push_back({"sun straight down", groundView(), sunFrom({0, -1, 0})});
    c.push_back({"sun parallel to view", groundView(), sunFrom({0, 0, -1})});
    c.push_back({"sun antiparallel to view", groundView(), sunFrom({0, 0, 1})});
    c.push_back({"looking down, sun down", groundView({0, -1, 0.001}), sunFrom({0, -1, 0})});
    ShadowLight spot;
    spot.kind = ShadowLightKind::Spot;
    spot.position = {10, 15, 20};
    spot.direction = glm::normalize(glm::dvec3(-0.3, -1, -0.5));
    spot.outerConeAngle = glm::radians(35.0);
    c.push_back({"spot ahead", groundView(), spot});
    spot.position = {0, 5, 70};  // behind the camera
    spot.direction = glm::normalize(glm::dvec3(0, -0.3, -1));
    c.push_back({"spot behind", groundView(), spot});
    spot.position = {0, 3, 40};  // inside the view frustum
    spot.direction = glm::normalize(glm::dvec3(0.2, -1, -0.3));
    spot.range = 20.0;
    c.push_back({"spot inside view", groundView(), spot});
    return c;
}

TEST(ShadowSetupInvariants, EveryVertexOfBLandsInTheClipCube) {
    for (const Config& c : configs()) {
        const ConvexBody B = intersectionBody(c.view, c.light, terrain());
        for (ShadowMethod m : kAllMethods) {
            SCOPED_TRACE(std::string(c.name) + " / method " + std::to_string(int(m)));
            const ShadowSetup s = setupFor(c.view, c.light, terrain(), m);
            expectBInClipCube(s, B);
            // No fallback: PSM runs without its guard here (shadow_setup_fixtures.h).
            EXPECT_TRUE(s.diagnostics.fallback.empty()) << s.diagnostics.fallback;
            // The diagnostics carry the bodies for the UI.
            EXPECT_EQ(s.diagnostics.bodyB.size(), B.faces().size());
            EXPECT_EQ(s.diagnostics.viewV.size(), 6u);
            EXPECT_FALSE(s.diagnostics.sceneS.empty());
        }
        expectVisiblePartInB(c.view, c.light, terrain(), 50);
    }
}

TEST(ShadowSetupInvariants, PointsBetweenLightAndVisibleReceiversAreInsideTheMap) {
    // A caster halfway between a visible point and the light must land inside the shadow map
    // (the depth range includes the casters, not just the receivers).
    for (const Config& c : configs()) {
        if (c.light.kind != ShadowLightKind::Directional) continue;
        ConvexBody vs;
        intersectionBody(c.view, c.light, terrain(), &vs);
        for (ShadowMethod m : kAllMethods) {
            const ShadowSetup s = setupFor(c.view, c.light, terrain(), m);
            for (const auto& p : vs.vertices()) {
                // Walk toward the light, staying inside the scene box.
                glm::dvec3 q = p;
                for (int i = 0; i < 20; ++i) {
                    const glm::dvec3 next = q - glm::normalize(c.light.direction) * 1.0;
                    if (next.x < -100 || next.x > 100 || next.y < 0 || next.y > 30 || next.z < -100 || next.z > 100)
                        break;
                    q = next;
                }
                const glm::dvec4 h = s.worldToShadowClip * glm::dvec4(q, 1.0);
                ASSERT_GT(h.w, 0.0) << c.name;
                EXPECT_LE(std::abs(h.z / h.w), 1.0 + 1e-4) << c.name << " method " << int(m);
                EXPECT_TRUE(casterCanReach(s, box(q - glm::dvec3(0.01), q + glm::dvec3(0.01)))) << c.name;
            }
        }
    }
}

// --- Linear depth, caster culling, bad input ----------------------------------------------------

TEST(ShadowSetup, LinearDepthCoversBAndGrowsAlongTheLight) {
    const ViewFrustum v = groundView();
    const ShadowLight l = sunFrom({1, -1, 0.3});
    const ShadowSetup s = setupFor(v, l, terrain(), ShadowMethod::Lispsm);
    ASSERT_TRUE(s.valid);
    const LinearShadowDepth& d = s.linearDepth;
    EXPECT_FALSE(d.radial);
    EXPECT_LT(d.nearDepth, d.farDepth);
    for (const auto& p : intersectionBody(v, l, terrain()).vertices()) {
        const double t = glm::dot(p - d.origin, d.axis);
        EXPECT_GE(t, d.nearDepth);
        EXPECT_LE(t, d.farDepth);
    }
    const glm::dvec3 a{0, 5, 0};
    EXPECT_LT(glm::dot(a - d.origin, d.axis), glm::dot(a + l.direction - d.origin, d.axis));
}

TEST(ShadowSetup, CasterCulling) {
    const ViewFrustum v = groundView();
    const ShadowLight l = sunFrom({0, -1, 0});
    const ShadowSetup s = setupFor(v, l, terrain(), ShadowMethod::Lispsm);
    ASSERT_TRUE(s.valid);
    // Above the visible ground: casts into the view.
    EXPECT_TRUE(casterCanReach(s, box({-1, 20, 20}, {1, 22, 22})));
    // Outside the view and not between it and the sun.
    EXPECT_FALSE(casterCanReach(s, box({80, 0, 80}, {90, 10, 90})));
    EXPECT_FALSE(casterCanReach(s, box({-1, 0, 70}, {1, 5, 72}))) << "behind the camera, sun overhead";
    // A huge box overlapping everything is kept; an empty one is not.
    EXPECT_TRUE(casterCanReach(s, terrain()));
    EXPECT_FALSE(casterCanReach(s, Aabb{}));
}

TEST(ShadowSetup, SpotCasterNearTheApexIsKept) {
    const ViewFrustum v = groundView();
    ShadowLight l;
    l.kind = ShadowLightKind::Spot;
    l.position = {0, 20, 20};
    l.direction = {0, -1, 0};
    l.outerConeAngle = glm::radians(30.0);
    const ShadowSetup s = setupFor(v, l, terrain(), ShadowMethod::SsmFocused);
    ASSERT_TRUE(s.valid);
    EXPECT_TRUE(s.linearDepth.radial);
    EXPECT_TRUE(casterCanReach(s, box(l.position - glm::dvec3(1e-4), l.position + glm::dvec3(1e-4))));
    EXPECT_TRUE(casterCanReach(s, box({-0.5, 15, 19.5}, {0.5, 16, 20.5})));
    EXPECT_FALSE(casterCanReach(s, box({-0.5, 21, 19.5}, {0.5, 22, 20.5}))) << "above (behind) the spot";
}

TEST(ShadowSetup, BadInputGivesAMessageNotACrash) {
    ViewFrustum v = groundView();
    v.eye.x = std::nan("");
    EXPECT_FALSE(setupFor(v, sunFrom({0, -1, 0}), terrain(), ShadowMethod::Lispsm).valid);
    v = groundView();
    v.zNear = 10.0;
    v.zFar = 1.0;
    const ShadowSetup s = setupFor(v, sunFrom({0, -1, 0}), terrain(), ShadowMethod::Psm);
    EXPECT_FALSE(s.valid);
    EXPECT_NE(s.diagnostics.fallback.find("zNear"), std::string::npos);
    EXPECT_FALSE(setupFor(groundView(), sunFrom({0, 0, 0}), terrain(), ShadowMethod::SsmFocused).valid);
    EXPECT_FALSE(setupFor(groundView(), sunFrom({0, -1, 0}), Aabb{}, ShadowMethod::SsmFocused).valid);
}

TEST(ShadowSetup, ZeroThicknessSceneStillShadows) {
    const ViewFrustum v = groundView({0, -0.3, -1});
    const Aabb ground = box({-100, 0, -100}, {100, 0, 100});
    const ShadowLight l = sunFrom({0.5, -1, 0.2});
    const ConvexBody B = intersectionBody(v, l, ground);
    ASSERT_FALSE(B.empty());
    EXPECT_EQ(B.bounds().extent().y, 0.0);
    for (ShadowMethod m : kAllMethods) expectBInClipCube(setupFor(v, l, ground, m), B);
}

}  // namespace
}  // namespace shadowlab

namespace shadowlab {
namespace {

// Shadow-map area (in NDC x/y units) of a small ground square.
double mapArea(const glm::dmat4& m, glm::dvec3 center, double half) {
    const glm::dvec3 c[4] = {center + glm::dvec3(-half, 0, -half), center + glm::dvec3(half, 0, -half),
                             center + glm::dvec3(half, 0, half), center + glm::dvec3(-half, 0, half)};
    double a = 0.0;
    for (int i = 0; i < 4; ++i) {
        const glm::dvec3 p = ndc(m, c[i]), q = ndc(m, c[(i + 1) % 4]);
        a += p.x * q.y - q.x * p.y;
    }
    return 0.5 * std::abs(a);
}

TEST(Warp, LispsmAndPsmGiveNearReceiversMoreOfTheMapThanSsm) {
    // Sun from the side, overhead-ish: the classic case where SSM wastes texels far away.
    const ViewFrustum v = groundView();
    const ShadowLight l = sunFrom({1, -0.6, 0});
    const glm::dvec3 nearPatch{0, 0, 45}, farPatch{0, 0, -20};
    auto ratio = [&](ShadowMethod m) {
        const ShadowSetup s = setupFor(v, l, terrain(), m);
        EXPECT_TRUE(s.valid);
        return mapArea(s.worldToShadowClip, nearPatch, 0.5) / mapArea(s.worldToShadowClip, farPatch, 0.5);
    };
    const double ssm = ratio(ShadowMethod::SsmFocused);
    EXPECT_NEAR(ssm, 1.0, 1e-9) << "a uniform map gives equal ground squares equal area";
    EXPECT_GT(ratio(ShadowMethod::Lispsm), 3.0 * ssm);
    EXPECT_GT(ratio(ShadowMethod::Psm), 3.0 * ssm);
}

}  // namespace
}  // namespace shadowlab

namespace shadowlab {
namespace {

TEST(Warp, SpotLispsmGivesNearReceiversMoreOfTheMapThanSsm) {
    // A spot high above and to the side, lighting the whole visible stretch of ground.
    const ViewFrustum v = groundView();
    ShadowLight l;
    l.kind = ShadowLightKind::Spot;
    l.position = {60, 40, 10};
    l.direction = glm::normalize(glm::dvec3(0, 0, 10) - l.position);
    l.outerConeAngle = glm::radians(60.0);
    const glm::dvec3 nearPatch{0, 0, 45}, farPatch{0, 0, -20};
    auto ratio = [&](ShadowMethod m) {
        const ShadowSetup s = setupFor(v, l, terrain(), m);
        EXPECT_TRUE(s.valid);
        return mapArea(s.worldToShadowClip, nearPatch, 0.5) / mapArea(s.worldToShadowClip, farPatch, 0.5);
    };
    const double ssm = ratio(ShadowMethod::SsmFocused), lispsm = ratio(ShadowMethod::Lispsm);
    EXPECT_GT(lispsm, 2.0 * ssm) << "ssm " << ssm << " lispsm " << lispsm;
}

}  // namespace
}  // namespace shadowlab

namespace shadowlab {
namespace {

// Depth must resolve the order ALONG each light ray, not mostly encode the position on the map:
// found through the renderer (a LiSPSM spot light lost every shadow), because the spot's
// post-projective y sits within 1e-4 of -1 over B and the fitted depth became ~ -image y.
// For every method and both light kinds, two points on one light ray 10 % of B's depth apart
// must differ in NDC depth by a sizeable fraction of the [-1, 1] range.
TEST(ShadowSetup, DepthResolvesTheOrderAlongLightRays) {
    const glm::dvec3 lightPos{5, 7, 3};
    ShadowLight spot;
    spot.kind = ShadowLightKind::Spot;
    spot.position = lightPos;
    spot.direction = glm::normalize(glm::dvec3(-1, 0, -1) - lightPos);
    spot.outerConeAngle = glm::radians(40.0);
    ShadowLight sun;
    sun.direction = glm::normalize(glm::dvec3(1.0, -0.8, 0.1));
    ViewFrustum v;
    v.eye = {0, 9, 11};
    v.forward = glm::normalize(glm::dvec3(0, -9, -11));
    v.fovY = glm::radians(60.0);
    v.aspect = 4.0 / 3.0;
    v.zNear = 0.1;
    v.zFar = 70.0;
    const Aabb scene = box({-10, -0.1, -10}, {10, 2, 10});
    for (const ShadowLight& light : {spot, sun})
        for (ShadowMethod m : kAllMethods) {
            ShadowParams p;
            p.method = m;
            const ShadowSetup s = computeShadowSetup(v, light, scene, p);
            ASSERT_TRUE(s.valid);
            // The box top's centre and the ground point it shadows, and a point 10 % further.
            const glm::dvec3 top{0, 2, 0};
            const glm::dvec3 dir = light.kind == ShadowLightKind::Spot ? glm::normalize(top - lightPos) : light.direction;
            const glm::dvec3 ground = top + dir * (2.0 / -dir.y);
            auto ndcZ = [&](glm::dvec3 q) {
                const glm::dvec4 h = s.worldToShadowClip * glm::dvec4(q, 1.0);
                return (s.reverseDepthTest ? -h.z : h.z) / h.w;
            };
            const double gap = ndcZ(ground) - ndcZ(top);
            EXPECT_GT(gap, 0.02) << "method " << int(m) << (light.kind == ShadowLightKind::Spot ? " spot" : " sun");
        }
}

}  // namespace
}  // namespace shadowlab
