// Loader speed (Google Benchmark, not a test): Sponza from disk, and the per-frame world update.
//   build-*/tests/scene/shadowlab_scene_bench
#include "scenes/gltf_loader.h"

#include <benchmark/benchmark.h>

namespace {

const std::string kSponza = std::string(SHADOWLAB_SHARED_SCENES) + "/Sponza/Sponza.gltf";

void BM_LoadSponza(benchmark::State& state) {
    for (auto _ : state) {
        shadowlab::LoadResult r = shadowlab::loadScene(kSponza);
        if (!r.ok()) {
            state.SkipWithError(r.error.c_str());
            break;
        }
        benchmark::DoNotOptimize(r.scene->triangleCount());
    }
}
BENCHMARK(BM_LoadSponza)->Unit(benchmark::kMillisecond)->UseRealTime();

// What animation pays per frame: world matrices, exact instance bounds, lights, cameras.
void BM_UpdateWorldTransformsSponza(benchmark::State& state) {
    shadowlab::LoadResult r = shadowlab::loadScene(kSponza);
    if (!r.ok()) {
        state.SkipWithError(r.error.c_str());
        return;
    }
    for (auto _ : state) {
        shadowlab::updateWorldTransforms(*r.scene);
        benchmark::DoNotOptimize(r.scene->bounds);
    }
}
BENCHMARK(BM_UpdateWorldTransformsSponza)->Unit(benchmark::kMicrosecond);

}  // namespace
