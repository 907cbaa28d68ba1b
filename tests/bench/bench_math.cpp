// CPU cost of the shadow setup per light per frame: B + matrix (+ diagnostics) per method, on a
// typical view: camera 2 m above a 1 km terrain looking slightly down, sun at 35 deg elevation
// from the side, spot light ahead of the camera. Goal: LiSPSM and PSM <= 10 us per light
// per frame and <= 1.5x SSM. The *_Receivers cases hand the ground y = 0 at the depth pre-pass's
// coarse and fine grids, as the renderer does (the warp search and the image check run); the
// *_Rescue case adds a far wall the sun grazes to the coarse grid, so the search keeps the
// uniform map and the image check scores the closed form's warps (math/image_check.h).
#include "math/shadow_setup.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

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

// The ground y = 0 seen at the centres of a gx x gy pixel grid (up to 300 m away).
std::vector<SurfacePoint> groundAtGrid(const ViewFrustum& v, int gx, int gy) {
    const glm::dvec3 f = glm::normalize(v.forward), r = glm::normalize(glm::cross(f, v.up)), u = glm::cross(r, f);
    const double ty = std::tan(0.5 * v.fovY), tx = ty * v.aspect;
    std::vector<SurfacePoint> out;
    for (int j = 0; j < gy; ++j)
        for (int i = 0; i < gx; ++i) {
            const glm::dvec3 d = f + r * ((-1.0 + (2.0 * i + 1.0) / gx) * tx) + u * ((-1.0 + (2.0 * j + 1.0) / gy) * ty);
            if (!(d.y < 0.0)) continue;
            const double t = -v.eye.y / d.y;
            if (t * glm::dot(d, f) < 300.0) out.push_back({v.eye + d * t, {0.0, 1.0, 0.0}});
        }
    return out;
}

enum class Receivers { None, Grids, GridsAndGrazedWall };

void run(benchmark::State& state, ShadowMethod method, const ShadowLight& light, bool polygons,
         Receivers receivers = Receivers::None) {
    const ViewFrustum v = typicalView();
    const Aabb s = typicalScene();
    ShadowParams p;
    p.method = method;
    p.collectPolygons = polygons;
    p.lispsm.virtualFar = 0.0;
    if (receivers != Receivers::None) {
        p.receiverPoints = groundAtGrid(v, ShadowParams::kReceiverGridX, ShadowParams::kReceiverGridY);
        p.fineReceiverPoints = groundAtGrid(v, ShadowParams::kFineReceiverGridX, ShadowParams::kFineReceiverGridY);
        p.lispsm.virtualFar = 300.0;
    }
    if (receivers == Receivers::GridsAndGrazedWall) {
        // A wall 250 m ahead whose normal is 0.3 degrees from perpendicular to the sun.
        const glm::dvec3 l = glm::normalize(light.direction);
        glm::dvec3 n = glm::normalize(glm::cross(l, glm::dvec3(0.0, 1.0, 0.0)));
        if (glm::dot(n, v.forward) > 0.0) n = -n;
        n = glm::normalize(n - l * std::sin(glm::radians(0.3)));
        p.receiverPoints.push_back({v.eye + glm::normalize(v.forward) * 250.0, n});
    }
    for (auto _ : state) {
        ShadowSetup setup = computeShadowSetup(v, light, s, p);
        benchmark::DoNotOptimize(setup.worldToShadowClip);
        benchmark::ClobberMemory();
    }
    // What the setup chose, so a case's cost can be read with its path (n = 1e300: uniform).
    const ShadowDiagnostics d = computeShadowSetup(v, light, s, p).diagnostics;
    state.counters["n"] = std::isfinite(d.nUsed) ? d.nUsed : 1e300;
    state.counters["imageCheckLoss"] = d.imageCheckLoss;
}

void BM_Sun_Ssm(benchmark::State& st) { run(st, ShadowMethod::SsmFocused, sun(), false); }
void BM_Sun_SsmUnfocused(benchmark::State& st) { run(st, ShadowMethod::SsmUnfocused, sun(), false); }
void BM_Sun_Psm(benchmark::State& st) { run(st, ShadowMethod::Psm, sun(), false); }
void BM_Sun_Lispsm(benchmark::State& st) { run(st, ShadowMethod::Lispsm, sun(), false); }
void BM_Sun_Lispsm_WithPolygons(benchmark::State& st) { run(st, ShadowMethod::Lispsm, sun(), true); }
void BM_Sun_Ssm_Receivers(benchmark::State& st) { run(st, ShadowMethod::SsmFocused, sun(), false, Receivers::Grids); }
void BM_Sun_Psm_Receivers(benchmark::State& st) { run(st, ShadowMethod::Psm, sun(), false, Receivers::Grids); }
void BM_Sun_Lispsm_Receivers(benchmark::State& st) { run(st, ShadowMethod::Lispsm, sun(), false, Receivers::Grids); }
void BM_Sun_Lispsm_Rescue(benchmark::State& st) {
    run(st, ShadowMethod::Lispsm, sun(), false, Receivers::GridsAndGrazedWall);
}
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
BENCHMARK(BM_Sun_Ssm_Receivers);
BENCHMARK(BM_Sun_Psm_Receivers);
BENCHMARK(BM_Sun_Lispsm_Receivers);
BENCHMARK(BM_Sun_Lispsm_Rescue);
BENCHMARK(BM_Spot_Ssm);
BENCHMARK(BM_Spot_Psm);
BENCHMARK(BM_Spot_Lispsm);

}  // namespace
}  // namespace shadowlab

BENCHMARK_MAIN();
