// Frame cost per shadow method on real scenes, headless (EGL): CPU ms of the whole frame and GPU ms
// of each pass from timer queries. On llvmpipe the GPU numbers are CPU rasterisation; run on a GPU
// machine for hardware timings.
//   shadowlab_bench_render [--benchmark_filter=...]   (scenes: the generated forest and Sponza)
#include "frame_setup.h"
#include "gl/debug_output.h"
#include "headless_context.h"
#include "render_target.h"
#include "renderer.h"
#include "scenes/gltf_loader.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <memory>

namespace shadowlab {
namespace {

struct SceneFixture {
    Scene scene;
    Settings settings;
};

std::unique_ptr<HeadlessContext> g_context;
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

void frameCost(benchmark::State& state, const std::string& file, ShadowMethod method) {
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
    RenderTarget target(1280, 720);
    std::map<std::string, double> gpuMs;
    FrameStats stats;
    int frames = 0;
    for (auto _ : state) {
        stats = renderer->render(f->scene, settings, 0.0, Viewport{target.framebuffer(), 0, 0, 1280, 720});
        glFinish();  // the frame's cost includes the GPU's work
        renderer->resolveTimings();
        ++frames;
    }
    stats = renderer->render(f->scene, settings, 0.0, Viewport{target.framebuffer(), 0, 0, 1280, 720});
    glFinish();
    renderer->resolveTimings();
    stats = renderer->render(f->scene, settings, 0.0, Viewport{target.framebuffer(), 0, 0, 1280, 720});
    for (const PassStats& p : stats.passes) {
        if (p.gpuMs > 0.0) state.counters["gpu_ms:" + p.name] = p.gpuMs;
        state.counters["cpu_ms:" + p.name] = p.cpuMs;
    }
    state.counters["triangles"] = double(stats.trianglesDrawn);
    state.counters["casters_drawn"] = double(stats.castersDrawn);
    state.counters["casters_culled"] = double(stats.castersCulled);
    state.counters["gl_errors"] = double(g_log.errorCount);
}

void registerScene(const std::string& name, const std::string& file) {
    for (ShadowMethod m : {ShadowMethod::SsmFocused, ShadowMethod::Psm, ShadowMethod::Lispsm})
        benchmark::RegisterBenchmark((name + "/" + methodName(m)).c_str(),
                                     [file, m](benchmark::State& s) { frameCost(s, file, m); })
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
