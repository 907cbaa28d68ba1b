// Culling cost against the instance count: view-frustum and caster culling through the
// instance BVH and by the linear loop, plus BVH build and refit, GL-free.
//   shadowlab_bench_culling [--benchmark_filter=...]
// Scenes: the generated forest at 10k instances (scale 1), 100k (scale 10) and 1M (the scale-1
// forest tiled 10 x 10 at its own spacing: `generate --scale` stops at 16). Each is culled for the
// forest's first camera preset (placed in the middle tile) and its sun, LiSPSM.
#include "culling/instance_culling.h"
#include "scenes/generators/scene_generators.h"
#include "scenes/gltf_loader.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>

namespace shadowlab {
namespace {

struct Fixture {
    Scene scene;
    InstanceCuller culler;
    ViewFrustum view;
    ShadowSetup setup;
    ClipPlanes planes;
};

std::unique_ptr<Scene> loadForest(double scale) {
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("shadowlab_bench_forest_" + std::to_string(int(scale)) + ".glb");
    if (!std::filesystem::exists(file)) {
        scenegen::GenerateOptions options;
        options.scale = scale;
        const scenegen::GenerateResult g = scenegen::generateScene("forest", options, file);
        if (!g.ok) {
            std::fprintf(stderr, "%s\n", g.error.c_str());
            return nullptr;
        }
    }
    LoadResult r = loadScene(file);
    if (!r.ok()) {
        std::fprintf(stderr, "%s\n", r.error.c_str());
        return nullptr;
    }
    return std::make_unique<Scene>(std::move(*r.scene));
}

// n x n copies of the scene's instances, `spacing` apart, centred on the original.
void tile(Scene& scene, int n, double spacing) {
    const std::vector<MeshInstance> base = scene.instances;
    scene.instances.clear();
    scene.instances.reserve(base.size() * std::size_t(n * n));
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const glm::dvec3 offset{(i - n / 2) * spacing, 0.0, (j - n / 2) * spacing};
            for (MeshInstance inst : base) {
                inst.world[3] += glm::dvec4(offset, 0.0);
                inst.worldBounds.min += offset;
                inst.worldBounds.max += offset;
                scene.instances.push_back(inst);
                scene.bounds.extend(inst.worldBounds);
            }
        }
}

Fixture* fixture(const std::string& name) {
    static std::map<std::string, std::unique_ptr<Fixture>> cache;
    if (auto it = cache.find(name); it != cache.end()) return it->second.get();
    auto scene = loadForest(name == "100k" ? 10.0 : 1.0);
    if (!scene) return cache.emplace(name, nullptr).first->second.get();
    auto f = std::make_unique<Fixture>();
    f->scene = std::move(*scene);
    if (name == "1M") tile(f->scene, 10, f->scene.bounds.extent().x);
    Settings s;
    s.camera = cameraFromScene(f->scene.cameras.front(), s.camera);
    s.method = ShadowMethod::Lispsm;
    f->view = viewFrustum(s.camera, 16.0 / 9.0);
    f->planes = clipPlanes(f->view.projectionMatrix() * f->view.viewMatrix());
    const LightFrame light = resolveLight(f->scene, s.light, 0.0);
    f->setup = computeShadowSetup(f->view, shadowLight(light), f->scene.bounds, shadowParams(s, f->view, f->scene.bounds));
    f->culler.setScene(f->scene);
    std::fprintf(stderr, "%s: %zu instances, BVH %zu nodes, depth %zu\n", name.c_str(), f->scene.instances.size(),
                 f->culler.hierarchy().nodeCount(), f->culler.hierarchy().depth());
    return cache.emplace(name, std::move(f)).first->second.get();
}

void cull(benchmark::State& state, const std::string& name, bool hierarchical) {
    Fixture* f = fixture(name);
    if (!f) {
        state.SkipWithError("cannot build the scene");
        return;
    }
    InstanceList visible, casters;
    for (auto _ : state) {
        f->culler.visible(f->scene, f->planes, hierarchical, visible);
        f->culler.casters(f->scene, f->setup, hierarchical, casters);
        benchmark::DoNotOptimize(visible.data());
        benchmark::DoNotOptimize(casters.data());
    }
    state.counters["instances"] = double(f->scene.instances.size());
    state.counters["instancesVisible"] = double(visible.size());
    state.counters["castersDrawn"] = double(casters.size());
}

void buildOrRefit(benchmark::State& state, const std::string& name, bool refit) {
    Fixture* f = fixture(name);
    if (!f) {
        state.SkipWithError("cannot build the scene");
        return;
    }
    InstanceCuller culler;
    culler.setScene(f->scene);
    for (auto _ : state) {
        if (refit) culler.updateInstances(f->scene);
        else culler.setScene(f->scene);
    }
    state.counters["instances"] = double(f->scene.instances.size());
}

}  // namespace
}  // namespace shadowlab

int main(int argc, char** argv) {
    using namespace shadowlab;
    for (const std::string name : {"10k", "100k", "1M"}) {
        for (bool hierarchical : {true, false})
            benchmark::RegisterBenchmark(("cull/" + name + (hierarchical ? "/bvh" : "/linear")).c_str(),
                                         [name, hierarchical](benchmark::State& s) { cull(s, name, hierarchical); })
                ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("bvh-build/" + name).c_str(),
                                     [name](benchmark::State& s) { buildOrRefit(s, name, false); })
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("bvh-refit/" + name).c_str(),
                                     [name](benchmark::State& s) { buildOrRefit(s, name, true); })
            ->Unit(benchmark::kMillisecond);
    }
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
