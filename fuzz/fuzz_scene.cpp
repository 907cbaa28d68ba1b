// libFuzzer target: bytes (GLB or .gltf JSON, told apart by the magic) -> the scene model, through
// everything up to GPU upload: container checks, tinygltf, budgets, accessor and image decoding,
// world transforms, defaults. External files resolve in a folder that does not exist, so the target
// reads nothing but its input. Budgets are smaller than the defaults so that one execution stays
// fast; the runner's -malloc_limit_mb then catches any allocation the budgets failed to bound.
#include "scenes/gltf_loader.h"

#include <cstddef>
#include <cstdint>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    shadowlab::LoadOptions options;
    options.limits.jsonBytes = 4u << 20;
    options.limits.nodes = 100000;
    options.limits.instances = 100000;
    options.limits.vertices = 1u << 20;
    options.limits.indices = 3u << 20;
    options.limits.drawnTriangles = 100000000;
    options.limits.animationKeys = 1u << 20;
    options.limits.texturePixels = 2048u * 2048u;
    options.limits.textureBytes = 64u << 20;
    const std::vector<unsigned char> bytes(data, data + size);
    const shadowlab::LoadResult result =
        shadowlab::loadSceneFromMemory(bytes, "fuzz.gltf", "/nonexistent-shadowlab-fuzz", options);
    // A failure must say why; a success must be a whole scene.
    if (!result.ok() && result.error.empty()) __builtin_trap();
    if (result.ok() && result.scene->cameras.empty()) __builtin_trap();
    return 0;
}
