// Frame cost per shadow method on real scenes, headless (EGL): CPU ms of the whole frame and GPU ms
// of each pass from timer queries, with every skip on and with each skip off in turn.
// On llvmpipe the GPU numbers are CPU rasterisation; run on a GPU machine for hardware timings.
//   shadowlab_bench_render [--benchmark_filter=...]   (scenes: the generated forest and Sponza)
// Benchmarks are named SCENE/METHOD/VARIANT/CAMERA: VARIANT is "all-skips", "no-<skip>" or
// "no-skips"; CAMERA is "still" (the same view every frame: the shadow map and the visible depth
// can be reused) or "moving" (the camera turns a little every frame: nothing view-dependent can).
// Counters use the keys of `shadowlab render --stats` (frame_stats.h), plus processCpuMsPerFrame:
// the CPU time of all threads per frame (on llvmpipe that includes the rasterisation). GPU ms from
// timer queries are not meaningful on llvmpipe, which rasterises when a framebuffer is flushed.
#include "frame/frame_setup.h"
#include "gl/debug_output.h"
#include "gl/headless_context.h"
#include "resources/render_target.h"
#include "renderer.h"
#include "scenes/gltf_loader.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <ctime>
#include <functional>
#include <map>
#include <memory>

namespace shadowlab {
namespace {

struct SceneFixture {
    Scene scene;
    Settings settings;
};

std::unique_ptr<HeadlessContext> g_context;

// CPU time of every thread of the process (llvmpipe rasterises on its own threads): the work a
// frame costs, less sensitive than wall time to other processes sharing the machine.
double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}
gl::DebugLog g_log;

const SceneFixture* sceneFixture(const std::string& file) {
    static std::map<std::string, std::unique_ptr<SceneFixture>> cache;
    auto it = cache.find(file);
    if (it != cache.end()) return it->second.get();
    LoadResult r = loadScene(file);
    if (!r.ok()) {
        std::fprintf(stderr, "%s\n", r.error.c_str());
        return cache.emplace(file, nullptr).first->second.get();
    }
    auto f = std::make_unique<SceneFixture>();
    f->scene = std::move(*r.scene);
    if (!f->scene.cameras.empty()) f->settings.camera = cameraFromScene(f->scene.cameras.front(), f->settings.camera);
    return cache.emplace(file, std::move(f)).first->second.get();
}

struct Variant {
    std::string name;
    std::function<void(SkipSettings&)> apply;
};

std::vector<Variant> variants() {
    return {{"all-skips", [](SkipSettings&) {}},
            {"no-reuseShadowMap", [](SkipSettings& k) { k.reuseShadowMap = false; }},
            {"no-hierarchicalCulling", [](SkipSettings& k) { k.hierarchicalCulling = false; }},
            {"no-asyncDepthReadback", [](SkipSettings& k) { k.asyncDepthReadback = false; }},
            {"no-groupedDraws", [](SkipSettings& k) { k.groupedDraws = false; }},
            {"no-shaderVariants", [](SkipSettings& k) { k.shaderVariants = false; }},
            {"no-clusterCulling", [](SkipSettings& k) { k.clusterCulling = false; }},
            {"no-skips", [](SkipSettings& k) { k = SkipSettings{false, false, false, false, false, false}; }}};
}

void frameCost(benchmark::State& state, const std::string& file, ShadowMethod method, const Variant& variant,
               bool moving) {
    const SceneFixture* f = sceneFixture(file);
    if (!f) {
        state.SkipWithError(("cannot load " + file).c_str());
        return;
    }
    std::string error;
    auto renderer = Renderer::create(error);
    if (!renderer) {
        state.SkipWithError(error.c_str());
        return;
    }
    renderer->setScene(f->scene);
    Settings settings = f->settings;
    settings.method = method;
    variant.apply(settings.skip);
    constexpr int kWidth = 1280, kHeight = 720;
    RenderTarget target(kWidth, kHeight);
    const Viewport viewport{target.framebuffer(), 0, 0, kWidth, kHeight};
    const double baseYaw = settings.camera.yawDeg;
    int frame = 0;
    auto renderOne = [&] {
        // Moving: +-0.2 degrees of yaw, never a cut, never the same view twice in a row.
        if (moving) {
            const int step = frame++;
            settings.camera.yawDeg = baseYaw + ((step % 2) ? 0.2 : -0.2) * (1.0 + 1e-3 * step);
        }
        FrameStats stats = renderer->render(f->scene, settings, 0.0, viewport);
        glFinish();  // the frame's cost includes the GPU's work
        return stats;
    };
    renderOne();
    renderOne();
    double culling = 0.0;
    std::size_t reused = 0, frames = 0;
    const double cpuStart = processCpuMs();
    for (auto _ : state) {
        const FrameStats stats = renderOne();
        culling += stats.cullingCpuMs;
        reused += stats.shadowMapReused ? 1 : 0;
        ++frames;
    }
    const double processMs = processCpuMs() - cpuStart;
    renderer->resolveTimings();
    const FrameStats& stats = renderer->lastFrameStats();
    state.counters["processCpuMsPerFrame"] = frames ? processMs / double(frames) : 0.0;
    for (const PassStats& p : stats.passes) {
        if (p.gpuMs > 0.0) state.counters["gpuMs:" + p.name] = p.gpuMs;
    }
    state.counters["drawCalls"] = double(stats.drawCalls);
    state.counters["shadowPass.drawCalls"] = double(stats.shadowPass.drawCalls);
    state.counters["shadowPass.triangles"] = double(stats.shadowPass.triangles);
    state.counters["forwardPass.drawCalls"] = double(stats.forwardPass.drawCalls);
    state.counters["instancesVisible"] = double(stats.instancesVisible);
    state.counters["castersDrawn"] = double(stats.castersDrawn);
    state.counters["cullingCpuMs"] = frames ? culling / double(frames) : 0.0;
    state.counters["shadowMapReused"] = frames ? double(reused) / double(frames) : 0.0;  // share of frames
    state.counters["gl_errors"] = double(g_log.errorCount);
}

void registerScene(const std::string& name, const std::string& file) {
    for (ShadowMethod m : {ShadowMethod::SsmFocused, ShadowMethod::Psm, ShadowMethod::Lispsm})
        for (const Variant& v : variants())
            for (bool moving : {false, true})
                benchmark::RegisterBenchmark(
                    (name + "/" + methodName(m) + "/" + v.name + "/" + (moving ? "moving" : "still")).c_str(),
                    [file, m, v, moving](benchmark::State& s) { frameCost(s, file, m, v, moving); })
                    ->Unit(benchmark::kMillisecond)
                    ->MinTime(2.0);
}

}  // namespace
}  // namespace shadowlab

int main(int argc, char** argv) {
    std::string error;
    shadowlab::g_context = shadowlab::HeadlessContext::create(error);
    if (!shadowlab::g_context) {
        std::fprintf(stderr, "%s\n", error.c_str());
        return 1;
    }
    shadowlab::gl::installDebugOutput(shadowlab::g_log);
    std::fprintf(stderr, "context: %s\n", shadowlab::g_context->description().c_str());
    shadowlab::registerScene("forest", SHADOWLAB_BUILD_SCENES "/forest.glb");
    shadowlab::registerScene("sponza", SHADOWLAB_SHARED_SCENES "/Sponza/Sponza.gltf");
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
