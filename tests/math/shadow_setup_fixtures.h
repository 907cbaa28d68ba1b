#pragma once
// Scenes, views, lights and checks shared by the shadow-setup tests (shadow_setup_test.cpp,
// shadow_setup_warps_test.cpp).
#include "math/shadow_setup.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace shadowlab::setup_test {

inline constexpr double kPi = 3.14159265358979323846;
inline const ShadowMethod kAllMethods[] = {ShadowMethod::SsmFocused, ShadowMethod::SsmUnfocused, ShadowMethod::Psm,
                                    ShadowMethod::Lispsm};

inline Aabb box(glm::dvec3 lo, glm::dvec3 hi) {
    Aabb b;
    b.min = lo;
    b.max = hi;
    return b;
}

// A terrain-like scene: 200 x 30 x 200, camera 2 above the ground looking along -z.
inline Aabb terrain() { return box({-100, 0, -100}, {100, 30, 100}); }
inline ViewFrustum groundView(glm::dvec3 forward = {0, 0, -1}) {
    ViewFrustum v;
    v.eye = {0, 2, 50};
    v.forward = glm::normalize(forward);
    v.up = {0, 1, 0};
    v.fovY = glm::radians(60.0);
    v.aspect = 1.5;
    v.zNear = 0.5;
    v.zFar = 80.0;
    return v;
}
// Depth of p along the view direction (what the cascade splits are placed in).
inline double eyeDepth(const ViewFrustum& v, const glm::dvec3& p) { return glm::dot(p - v.eye, glm::normalize(v.forward)); }

inline ShadowLight sunFrom(glm::dvec3 travel) {
    ShadowLight l;
    l.kind = ShadowLightKind::Directional;
    l.direction = glm::normalize(travel);
    return l;
}

// PSM without its guard: these fixtures have no measured receivers, without which the guard
// always keeps the focused SSM; the tests check the parameterization itself.
inline ShadowSetup setupFor(const ViewFrustum& v, const ShadowLight& l, const Aabb& s, ShadowMethod m,
                     LispsmParams lp = {}) {
    ShadowParams p;
    p.method = m;
    p.lispsm = lp;
    p.psmGuard = false;
    return computeShadowSetup(v, l, s, p);
}

inline glm::dvec3 ndc(const glm::dmat4& m, const glm::dvec3& p) {
    const glm::dvec4 h = m * glm::dvec4(p, 1.0);
    return glm::dvec3(h) / h.w;
}

// Every vertex of B maps into [-1, 1]^3 (tolerance 1e-4) with w > 0.
inline void expectBInClipCube(const ShadowSetup& s, const ConvexBody& B) {
    ASSERT_TRUE(s.valid);
    for (const auto& p : B.vertices()) {
        const glm::dvec4 h = s.worldToShadowClip * glm::dvec4(p, 1.0);
        ASSERT_GT(h.w, 0.0);
        EXPECT_LE(std::abs(h.x / h.w), 1.0 + 1e-4);
        EXPECT_LE(std::abs(h.y / h.w), 1.0 + 1e-4);
        EXPECT_LE(std::abs(h.z / h.w), 1.0 + 1e-4);
    }
}

// Random points of V n S (convex combinations of its corners) all lie in B.
inline void expectVisiblePartInB(const ViewFrustum& v, const ShadowLight& l, const Aabb& s, int samples = 200) {
    ConvexBody vs;
    const ConvexBody B = intersectionBody(v, l, s, &vs);
    ASSERT_FALSE(vs.empty());
    std::mt19937_64 g(42);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const auto verts = vs.vertices();
    for (int i = 0; i < samples; ++i) {
        glm::dvec3 p{0.0};
        double w = 0.0;
        for (const auto& q : verts) {
            const double a = std::pow(u(g), 4.0);
            p += a * q;
            w += a;
        }
        p /= w;
        EXPECT_TRUE(B.contains(p, 1e-9)) << p.x << " " << p.y << " " << p.z;
    }
}

// --- ViewFrustum ------------------------------------------------------------------------------

}  // namespace shadowlab::setup_test
