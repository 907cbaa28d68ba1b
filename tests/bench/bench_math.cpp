// CPU cost of the shadow setup per light per frame: B + matrix (+ diagnostics) per method, on a
// typical view: camera 2 m above a 1 km terrain looking slightly down, sun at 35 deg elevation
// from the side, spot light ahead of the camera. Goal: LiSPSM and PSM <= 10 us per light
// per frame and <= 1.5x SSM.
#include "math/shadow_setup.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace shadowlab {
namespace {

ViewFrustum typicalView() {
    ViewFrustum v;
    v.eye = {10.0, 2.0, 20.0};
    v.forward = glm::normalize(glm::dvec3(0.3, -0.15, -1.0));
    v.up = {0, 1, 0};
    v.fovY = glm::radians(60.0);
    v.aspect = 16.0 / 9.0;
    v.zNear = 0.1;
    v.zFar = 800.0;
    return v;
}

Aabb typicalScene() {
    Aabb s;
    s.min = {-500.0, -5.0, -500.0};
    s.max = {500.0, 60.0, 500.0};
    return s;
}

ShadowLight sun() {
    ShadowLight l;
    l.kind = ShadowLightKind::Directional;
    const double el = glm::radians(35.0), az = glm::radians(70.0);
    l.direction = -glm::dvec3(std::cos(el) * std::cos(az), std::sin(el), std::cos(el) * std::sin(az));
    return l;
}

ShadowLight spot() {
    ShadowLight l;
    l.kind = ShadowLightKind::Spot;
    l.position = {20.0, 15.0, -10.0};
    l.direction = glm::normalize(glm::dvec3(-0.2, -1.0, -0.3));
    l.outerConeAngle = glm::radians(40.0);
    l.range = 80.0;
    return l;
}

void run(benchmark::State& state, ShadowMethod method, const ShadowLight& light, bool polygons) {
    const ViewFrustum v = typicalView();
    const Aabb s = typicalScene();
    ShadowParams p;
    p.method = method;
    p.collectPolygons = polygons;
    p.lispsm.virtualFar = 0.0;
    for (auto _ : state) {
        ShadowSetup setup = computeShadowSetup(v, light, s, p);
        benchmark::DoNotOptimize(setup.worldToShadowClip);
        benchmark::ClobberMemory();
    }
}

void BM_Sun_Ssm(benchmark::State& st) { run(st, ShadowMethod::SsmFocused, sun(), false); }
void BM_Sun_SsmUnfocused(benchmark::State& st) { run(st, ShadowMethod::SsmUnfocused, sun(), false); }
void BM_Sun_Psm(benchmark::State& st) { run(st, ShadowMethod::Psm, sun(), false); }
void BM_Sun_Lispsm(benchmark::State& st) { run(st, ShadowMethod::Lispsm, sun(), false); }
void BM_Sun_Lispsm_WithPolygons(benchmark::State& st) { run(st, ShadowMethod::Lispsm, sun(), true); }
void BM_Spot_Ssm(benchmark::State& st) { run(st, ShadowMethod::SsmFocused, spot(), false); }
void BM_Spot_Psm(benchmark::State& st) { run(st, ShadowMethod::Psm, spot(), false); }
void BM_Spot_Lispsm(benchmark::State& st) { run(st, ShadowMethod::Lispsm, spot(), false); }

void BM_IntersectionBody_Sun(benchmark::State& st) {
    const ViewFrustum v = typicalView();
    const Aabb s = typicalScene();
    const ShadowLight l = sun();
    for (auto _ : st) {
        ConvexBody b = intersectionBody(v, l, s);
        benchmark::DoNotOptimize(b);
    }
}

BENCHMARK(BM_IntersectionBody_Sun);
BENCHMARK(BM_Sun_Ssm);
BENCHMARK(BM_Sun_SsmUnfocused);
BENCHMARK(BM_Sun_Psm);
BENCHMARK(BM_Sun_Lispsm);
BENCHMARK(BM_Sun_Lispsm_WithPolygons);
BENCHMARK(BM_Spot_Ssm);
BENCHMARK(BM_Spot_Psm);
BENCHMARK(BM_Spot_Lispsm);

}  // namespace
}  // namespace shadowlab

BENCHMARK_MAIN();
