#pragma once
// Shared by the loader's files (not part of the public API): the failure type, message helpers,
// the container checks and the Converter that turns a parsed tinygltf model into a Scene.
//   gltf_container.cpp   file bytes, GLB layout, JSON size/depth, asset and extensions
//   gltf_accessors.cpp   byte ranges and accessor decoding (sparse, normalized, shared)
//   gltf_textures.cpp    image capture, header checks and the texture budget, decoding
//   image_decode.cpp     stb_image compiled privately, every allocation bounded by the header
//   gltf_meshes.cpp      materials, primitives, the geometry budget
//   gltf_nodes.cpp       nodes, lights, cameras, the instance budget, animations
//   gltf_deform.cpp      skins, JOINTS_0/WEIGHTS_0, morph targets, node morph weights
//   gltf_draco.cpp       KHR_draco_mesh_compression into plain accessors
//   gltf_meshopt.cpp     EXT/KHR_meshopt_compression into plain bufferViews
//   gltf_glb_bin.cpp     a large GLB's BIN chunk handed to tinygltf without its copy
//   gltf_loader.cpp      the steps in order, load limits
#include "scenes/bulk_buffer.h"
#include "scenes/gltf_loader.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace shadowlab::gltf {

using json = nlohmann::json;

struct LoadFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

[[noreturn]] inline void fail(const std::string& reason) { throw LoadFailure(reason); }

// Names come from the file: a 50 MB name must not become a 50 MB message.
inline std::string quoted(const std::string& name) {
    return "'" + (name.size() > 80 ? name.substr(0, 77) + "..." : name) + "'";
}

// "mesh 3 'Arch'" style labels: messages must let a user find the object in the file.
std::string label(const char* kind, std::size_t index, const std::string& name);

// "exceeds the load limit vertices = 33554432 (raise it with --limit vertices=N)"
std::string overLimit(const char* key, std::uint64_t limit);

// Multi-line tinygltf/stb messages as one line.
std::string cleanMessage(const std::string& text);

// ---------------------------------------------------------------- container (gltf_container.cpp)
// A file's bytes: read once, parsed, freed before the conversion (scenes/bulk_buffer.h).
using FileBytes = BulkVector<unsigned char>;
// The whole file, refused before reading when it is not a regular file (a FIFO would block, a
// device never end) or larger than limits.fileBytes.
FileBytes readFileBytes(const std::filesystem::path& file, const LoadLimits& limits);
bool isGlb(const FileBytes& bytes);
// The GLB layout (glTF 2.0 spec, "Binary glTF Layout"); returns the JSON chunk.
std::string checkGlb(const FileBytes& bytes);
// Size and nesting depth checked on the text before a DOM is built (a deep file would otherwise
// exhaust the stack of a recursive consumer); parse errors with line and column.
json parseJson(const std::string& text, const LoadLimits& limits);
void checkAssetAndExtensions(const json& root, std::vector<std::string>& warnings);
void checkDeclaredCounts(const json& root, const LoadLimits& limits);
void checkExternalFiles(const json& root, const std::filesystem::path& baseDir);

const json* member(const json& object, const char* key);
// The JSON text tinygltf should parse when it differs from the file's (compressed data it would
// refuse before the decoders run: Draco index accessors, meshopt fallback buffers); nullopt if not.
std::optional<std::string> tinygltfJson(const json& root);
// The GLB with its JSON chunk replaced by `jsonText` (checkGlb has checked the layout).
FileBytes glbWithJson(const FileBytes& glb, const std::string& jsonText);

// ---------------------------------------------------------------- GLB BIN handoff (gltf_glb_bin.cpp)
struct GlbBinHandoff {
    std::string jsonText;            // the JSON with buffer 0 named by a marker URI
    std::vector<unsigned char> bin;  // buffer 0's bytes, given to tinygltf by swap
};
// For a GLB whose BIN chunk is at least 4 MB and larger than its JSON, buffer 0 takes the chunk and
// every other buffer has a URI; nullopt otherwise (tinygltf's binary parse, its own messages).
std::optional<GlbBinHandoff> glbBinHandoff(const FileBytes& glb, const json& root);
// tinygltf's parse of handoff.jsonText; the marker's file callback hands over handoff.bin.
bool parseWithHandoff(tinygltf::TinyGLTF& gltf, tinygltf::Model& model, std::string& err, std::string& warn,
                      GlbBinHandoff& handoff, const std::string& baseDir);

// ---------------------------------------------------------------- compressed geometry
// Run on tinygltf's model before the conversion: compressed data decoded into plain buffers,
// bufferViews and accessors, so that the converter reads every attribute the same way.
// KHR_draco_mesh_compression (gltf_draco.cpp): the primitives re-pointed at decoded accessors.
void decodeDracoPrimitives(tinygltf::Model& model, const json& root, const LoadLimits& limits);
// EXT/KHR_meshopt_compression (gltf_meshopt.cpp): compressed bufferViews re-pointed at decoded bytes.
void decodeMeshoptViews(tinygltf::Model& model, const json& root, const LoadLimits& limits);

// ---------------------------------------------------------------- images (gltf_textures.cpp)
// Images are captured encoded while tinygltf parses; only those a base colour texture uses are
// looked at afterwards (Sponza's normal and roughness maps are never decoded).
struct ImageCapture {
    const tinygltf::Model* model = nullptr;
    std::vector<char> wanted;  // per image: a base colour texture uses it (others are not kept)
    std::map<int, std::shared_ptr<const std::vector<std::uint8_t>>> encoded;
};
// The image a texture shows: EXT_texture_webp's source, else the core (PNG/JPEG) source; a
// KHR_texture_basisu source is never decoded (no Basis Universal decoder is packaged), so a
// texture with only that has image -1 and its materials use their factors.
struct TextureSource {
    int image = -1;
    bool basisuSkipped = false;  // the texture names a KTX2 image that is not used
};
TextureSource textureSource(const json& texture);
// The images that materials' base colour textures name, from the JSON (before tinygltf's parse).
std::vector<char> baseColorImages(const json& root);
bool captureImage(tinygltf::Image* image, int index, std::string* err, std::string* warn, int reqWidth,
                  int reqHeight, const unsigned char* bytes, int size, void* user);

// ---------------------------------------------------------------- progress (LoadOptions::progress)
// Where each step ends, as a fraction of the whole load: Sponza's times (glTF, 1.22 s on this
// 2-core machine, LoaderProgress test: read and JSON 0.005 s, tinygltf's parse with the buffers
// 0.20 s, meshes ~0.1 s, its 21 base colour textures 0.9 s). A scene without textures to decode
// gives the meshes the textures' span (meshesWithoutTextures).
struct LoadProgress {
    double read = 0.01, json = 0.02, parsed = 0.18, nodes = 0.19, meshes = 0.28, textures = 0.99;
    double meshesWithoutTextures = 0.99;
};
inline constexpr LoadProgress kLoadProgress{};
inline void reportProgress(const LoadOptions& options, double fraction) {
    if (options.progress) options.progress(fraction);
}

// ---------------------------------------------------------------- the model -> Scene conversion
class Converter {
public:
    Converter(const tinygltf::Model& model, const json& rootJson, const ImageCapture& capture,
              const LoadOptions& options, std::vector<std::string>& warnings, Scene& target);
    // Nodes first (cheap, gives the instance count), then every budget from the declared counts,
    // then the decoding.
    void convert();

private:
    const tinygltf::Model& m;
    const json& root;
    const ImageCapture& images;
    const LoadOptions& options;
    std::vector<std::string>& warnings;
    Scene& scene;

    void warn(const std::string& message) { warnings.push_back(message); }

    // accessors (gltf_accessors.cpp)
    struct DecodedAccessor {
        BulkVector<float> values;            // count * components (attributes)
        std::vector<std::uint32_t> indices;  // count (index accessors)
        std::size_t count = 0;
    };
    // Accessors referenced by more than one primitive are decoded once and kept until their last
    // user is done (a mesh whose primitives share one POSITION accessor is the common case).
    using AccessorUse = std::tuple<int, int, bool>;  // accessor, components, integerOnly
    std::map<AccessorUse, int> accessorUsers;
    std::map<AccessorUse, std::shared_ptr<DecodedAccessor>> accessorCache;
    const unsigned char* viewRange(int viewIndex, std::size_t byteOffset, std::size_t count, std::size_t elementSize,
                                   bool useViewStride, std::size_t& stride, const std::string& what) const;
    template <class Vector>
    Vector decodeAccessor(int index, const std::string& what, int wantComponents, bool integerOnly,
                                  std::size_t& count) const;
    std::vector<double> readAccessor(int index, const std::string& what, int wantComponents, bool integerOnly,
                                     std::size_t& count) const;
    // Attributes as floats, index accessors (integerOnly, 1 component) as uint32. The caller that
    // holds the only reference may take the arrays.
    std::shared_ptr<DecodedAccessor> sharedAccessor(int index, const std::string& what, int wantComponents,
                                                    bool integerOnly);
    void countAccessorUsers();

    // textures and materials (gltf_textures.cpp, gltf_meshes.cpp)
    struct TextureKey {
        int image;
        int sampler;
        auto operator<=>(const TextureKey&) const = default;
    };
    std::map<int, int> textureSlots;        // glTF texture -> Scene::textures (-1: drawn untextured)
    std::map<TextureKey, int> sharedSlots;  // (image, sampler) -> Scene::textures: one decode each
    std::vector<int> slotImages;            // Scene::textures -> glTF image
    std::uint64_t textureBytes = 0;
    int useTexture(int gltfTexture, const std::string& what);
    bool imageFitsBudget(int image, int& width, int& height);
    void decodeTextures();
    void convertMaterials();
    bool textureTransform(int material, glm::dmat3& transform) const;

    // meshes (gltf_meshes.cpp)
    std::vector<std::uint64_t> meshTriangles;  // declared triangles per glTF mesh (for the instance budget)
    void checkGeometryBudget();
    std::optional<Primitive> convertPrimitive(const tinygltf::Primitive& src, const std::string& where);
    void convertMeshes();

    // nodes, lights, cameras, animations (gltf_nodes.cpp)
    std::vector<int> reachableOrder;  // nodes of the displayed scene, depth first
    int nodeLight(std::size_t nodeIndex) const;
    void convertNodes();
    void checkInstanceBudget() const;
    void addLight(int gltfLight, int node);
    void addCamera(int gltfCamera, int node);
    void convertAnimations();

    // skins and morph targets (gltf_deform.cpp)
    void convertSkins();
    void readSkinAttributes(const tinygltf::Primitive& src, const std::string& where, Primitive& p);
    void readMorphTargets(const tinygltf::Primitive& src, const std::string& where, Primitive& p) const;
    // After meshes: node skins checked against their meshes' joints, node morph weights set, and a
    // deformed mesh drawn by several nodes copied per node (each pose deforms its own vertices).
    void finishDeformedNodes();
    int morphTargetCount(int node) const;  // of the node's mesh, 0 without
};

// Every element finite (doubles of the JSON's factors, decoded float attributes alike).
template <class Values>
bool finiteAll(const Values& v) {
    return std::all_of(v.begin(), v.end(), [](auto x) { return std::isfinite(x); });
}

}  // namespace shadowlab::gltf
