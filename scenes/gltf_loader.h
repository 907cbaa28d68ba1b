#pragma once
// glTF 2.0 (.gltf with external or data-URI resources, .glb) into the project's scene model.
// tinygltf parses; everything it does not check (accessor ranges, sparse substitution, index
// ranges, non-finite numbers, required extensions, node cycles) is validated here before use.
#include "scenes/load_timings.h"
#include "scenes/scene.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace shadowlab {

// Resource budgets, checked from the file's declared counts and image headers before anything is
// allocated, so that a small hostile file is refused in milliseconds instead of eating the machine.
// The defaults open every real scene we know (Sponza, the generated forest up to --scale 16,
// city-scale scenes and interiors of a few million triangles); `--limit KEY=VALUE` raises one.
struct LoadLimits {
    std::uint64_t fileBytes = 4294967295ull;      // the container (GLB lengths are 32-bit)
    std::uint64_t jsonBytes = 128ull << 20;       // the JSON text (.gltf file or GLB JSON chunk)
    std::uint64_t jsonDepth = 64;                 // nesting of arrays/objects (glTF needs < 10)
    std::uint64_t nodes = 2000000;                // the "nodes" array
    std::uint64_t instances = 2000000;            // mesh instances after flattening the hierarchy
    std::uint64_t vertices = 32ull << 20;         // decoded vertices, summed over all primitives
    std::uint64_t indices = 96ull << 20;          // triangle-list indices after strip/fan expansion
    std::uint64_t drawnTriangles = 1000000000ull; // triangles drawn per frame (instances x mesh)
    std::uint64_t animationKeys = 16ull << 20;    // keyframe values summed over all channels
    std::uint64_t texturePixels = 8192ull * 8192; // one image (width x height from its header)
    std::uint64_t textureBytes = 1ull << 30;      // all decoded RGBA8 textures together
};

// What happens to base colour images: Decode (default: RGBA8 pixels in Texture::rgba8), Deferred
// (only the header's size; the encoded bytes are kept in Texture::encoded for decodeTexture, e.g.
// to show the geometry first and stream the pixels in) or HeadersOnly (size only: `info`).
enum class TextureDecoding { Decode, Deferred, HeadersOnly };

struct LoadOptions {
    LoadLimits limits;
    TextureDecoding textures = TextureDecoding::Decode;
    // The glTF scene to show: -1 for the file's default ("scene", else the first); an index past the
    // file's scenes is an error that names how many it has.
    int sceneIndex = -1;
    // The fraction done (0 .. 1, never decreasing), after each step: the file read, the JSON,
    // tinygltf's parse, each mesh, each decoded texture (kLoadProgress in gltf_internal.h weighs
    // the steps). Called on the loading thread only, never concurrently; a viewer on another
    // thread should keep the value in an atomic. Empty: no calls.
    std::function<void(double)> progress;
    // When set, each step adds its milliseconds here (`info --timings`).
    LoadTimings* timings = nullptr;
};

struct LoadResult {
    std::optional<Scene> scene;         // empty on failure: never a half-loaded scene
    std::string error;                  // "<file>: <reason>" when scene is empty
    std::vector<std::string> warnings;  // also kept in Scene::warnings
    bool ok() const { return scene.has_value(); }
};

// Loads a .gltf or .glb (the container is told by the file's magic, not its name).
// Never throws and never crashes on bad input; adds the default sun / framing camera.
// Thread-safe: no shared state, so scenes may be loaded on a worker thread while another renders.
LoadResult loadScene(const std::filesystem::path& file, const LoadOptions& options = {});

// The same from bytes already in memory (a fuzzer, a network): `name` names it in messages and
// (by its extension) tells a .glb without the magic apart; external files resolve in `baseDir`.
LoadResult loadSceneFromMemory(const std::vector<unsigned char>& bytes, const std::filesystem::path& name,
                               const std::filesystem::path& baseDir, const LoadOptions& options = {});

// Decodes a texture loaded with TextureDecoding::Deferred into rgba8 and drops its encoded bytes.
// Touches only `texture`: textures may be decoded on several threads at once. False with `error`.
bool decodeTexture(Texture& texture, std::string& error);

// `--limit vertices=64e6` style (KEY as in LoadLimits, VALUE a non-negative integer, exponent allowed).
bool setLoadLimit(LoadLimits& limits, std::string_view keyEqualsValue, std::string& error);
// One line per limit: "vertices = 33554432  decoded vertices, summed over all primitives".
std::vector<std::string> describeLoadLimits(const LoadLimits& limits);

// Adds a default sun (directional, from above and slightly sideways, "Default Sun",
// Scene::defaultLight) when the scene has no light, and a framing perspective camera
// (yfov 60 degrees, looking at the bounds from a diagonal, near/far from the bounds,
// Scene::defaultCamera) when it has no camera. Needs up-to-date bounds (updateWorldTransforms).
void addDefaultsIfMissing(Scene& scene);

// Recomputes Node::world from the local TRS/matrix down from the roots, rebuilds the mesh
// instances (world matrix, world bounds, mirroring) of the nodes reachable from the roots,
// places the node lights and cameras, and recomputes Scene::bounds (skinned and morphed instances:
// bounds that hold for the current pose, scenes/skinning.h). Animation calls it per frame.
// A scene without roots treats every parentless node as a root.
void updateWorldTransforms(Scene& scene);

// Local transform of a node: its matrix, or T * R * S.
glm::dmat4 localTransform(const Node& node);

// The multi-line text `shadowlab info` prints.
std::string describeScene(const Scene& scene);

}  // namespace shadowlab
