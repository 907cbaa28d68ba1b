// Loader speed (Google Benchmark, not a test): Sponza from disk, and the per-frame world update.
//   build-*/tests/scene/shadowlab_scene_bench
#include "scenes/animation.h"
#include "scenes/gltf_loader.h"
#include "scenes/skinning.h"

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

// The image decoders alone: Sponza's base colour textures (PNG and JPEG) decoded one after the
// other on one thread (the loader decodes them in parallel).
void BM_DecodeSponzaTextures(benchmark::State& state) {
    shadowlab::LoadOptions options;
    options.textures = shadowlab::TextureDecoding::Deferred;
    shadowlab::LoadResult r = shadowlab::loadScene(kSponza, options);
    if (!r.ok()) {
        state.SkipWithError(r.error.c_str());
        return;
    }
    for (auto _ : state) {
        for (const shadowlab::Texture& texture : r.scene->textures) {
            shadowlab::Texture copy = texture;
            std::string error;
            if (!shadowlab::decodeTexture(copy, error)) state.SkipWithError(error.c_str());
            benchmark::DoNotOptimize(copy.rgba8.data());
        }
    }
    state.counters["textures"] = double(r.scene->textures.size());
}
BENCHMARK(BM_DecodeSponzaTextures)->Unit(benchmark::kMillisecond)->UseRealTime();

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

const std::string kCesiumMan = std::string(SHADOWLAB_SHARED_SCENES) + "/CesiumMan/glTF-Binary/CesiumMan.glb";

// A skinned character's per-frame CPU share: the animation sampled, world matrices, and the pose's
// bounds from the per-joint boxes (no vertex touched).
void BM_PoseCesiumMan(benchmark::State& state) {
    shadowlab::LoadResult r = shadowlab::loadScene(kCesiumMan);
    if (!r.ok()) {
        state.SkipWithError(r.error.c_str());
        return;
    }
    double t = 0.0;
    for (auto _ : state) {
        shadowlab::animateScene(*r.scene, t += 0.01);
        benchmark::DoNotOptimize(r.scene->bounds);
    }
}
BENCHMARK(BM_PoseCesiumMan)->Unit(benchmark::kMicrosecond);

// What skinning every vertex on the CPU would cost per pose (the truth does it once per build;
// the GPU's deform.comp does it for drawing).
void BM_DeformCesiumManOnCpu(benchmark::State& state) {
    shadowlab::LoadResult r = shadowlab::loadScene(kCesiumMan);
    if (!r.ok()) {
        state.SkipWithError(r.error.c_str());
        return;
    }
    shadowlab::Scene& s = *r.scene;
    shadowlab::animateScene(s, 0.5);
    std::vector<glm::vec3> positions, normals;
    for (auto _ : state)
        for (const shadowlab::MeshInstance& instance : s.instances) {
            const shadowlab::Pose pose = shadowlab::instancePose(s, instance);
            for (const shadowlab::Primitive& p : s.meshes[std::size_t(instance.mesh)].primitives) {
                shadowlab::deformPrimitive(p, pose, positions, &normals);
                benchmark::DoNotOptimize(positions.data());
            }
        }
}
BENCHMARK(BM_DeformCesiumManOnCpu)->Unit(benchmark::kMicrosecond);

}  // namespace
