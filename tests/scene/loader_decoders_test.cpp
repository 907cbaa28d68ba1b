// Compressed geometry and images through their decoders, on files encoded here with the same
// libraries' encoders: Draco (KHR_draco_mesh_compression), meshopt (EXT_meshopt_compression),
// WebP (EXT_texture_webp); KTX2 (KHR_texture_basisu) refused or passed over; several scenes in
// one file. Each decodes to what the plain file gives, and each corruption is a clear message.
#include "gltf_fixture.h"
#include "scenes/gltf_loader.h"

#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <gtest/gtest.h>
#include <meshoptimizer.h>
#include <webp/encode.h>

#include <chrono>
#include <cstring>

namespace shadowlab {
namespace {

using namespace testing_files;

const float kQuad[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
const std::uint32_t kQuadIndices[6] = {0, 1, 2, 0, 2, 3};

// The quad as a Draco stream; `sequential` picks the encoding whose header the loader reads first.
Bytes dracoQuad(bool sequential, int& positionId) {
    draco::TriangleSoupMeshBuilder builder;
    builder.Start(2);
    positionId = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
    for (int f = 0; f < 2; ++f) {
        const float* v[3];
        for (int c = 0; c < 3; ++c) v[c] = kQuad + 3 * kQuadIndices[3 * f + c];
        builder.SetAttributeValuesForFace(positionId, draco::FaceIndex(f), v[0], v[1], v[2]);
    }
    std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
    positionId = int(mesh->attribute(positionId)->unique_id());
    draco::Encoder encoder;
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 12);
    if (sequential) encoder.SetEncodingMethod(draco::MESH_SEQUENTIAL_ENCODING);
    draco::EncoderBuffer out;
    EXPECT_TRUE(encoder.EncodeMeshToBuffer(*mesh, &out).ok());
    return Bytes(out.data(), out.data() + out.size());
}

// A GLB whose one primitive is the Draco `stream`.
Bytes dracoGlb(const Bytes& stream, int positionId) {
    Bytes bin = stream;
    pad4(bin);
    const json j = {
        {"asset", {{"version", "2.0"}}},
        {"extensionsUsed", {"KHR_draco_mesh_compression"}},
        {"extensionsRequired", {"KHR_draco_mesh_compression"}},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"meshes",
         {{{"primitives",
            {{{"attributes", {{"POSITION", 0}}},
              {"indices", 1},
              {"extensions",
               {{"KHR_draco_mesh_compression", {{"bufferView", 0}, {"attributes", {{"POSITION", positionId}}}}}}}}}}}}},
        {"accessors",
         {{{"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
          {{"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}},
        {"bufferViews", {{{"buffer", 0}, {"byteLength", stream.size()}}}},
        {"buffers", {{{"byteLength", bin.size()}}}},
    };
    return glb(j, bin);
}

std::vector<glm::vec3> corners(const Primitive& p) {
    std::vector<glm::vec3> out;
    for (std::uint32_t i : p.indices) out.push_back(p.positions[i]);
    return out;
}

class Decoders : public LoaderFiles {};

TEST_F(Decoders, DracoQuadLoadsAsThePlainOne) {
    for (const bool sequential : {false, true}) {
        SCOPED_TRACE(sequential ? "sequential" : "edgebreaker");
        int id = 0;
        const Scene s = expectLoads(write("draco.glb", dracoGlb(dracoQuad(sequential, id), id)));
        ASSERT_EQ(s.meshes.size(), 1u);
        ASSERT_EQ(s.meshes[0].primitives.size(), 1u);
        const Primitive& p = s.meshes[0].primitives[0];
        ASSERT_EQ(p.indices.size(), 6u);
        // The corners of both triangles, in any rotation of each triangle's vertex order.
        std::vector<glm::vec3> got = corners(p), want;
        for (std::uint32_t i : kQuadIndices) want.emplace_back(kQuad[3 * i], kQuad[3 * i + 1], kQuad[3 * i + 2]);
        auto near = [](glm::vec3 a, glm::vec3 b) { return glm::length(a - b) < 1e-3f; };
        for (const glm::vec3& w : want)
            EXPECT_TRUE(std::any_of(got.begin(), got.end(), [&](glm::vec3 g) { return near(g, w); }))
                << w.x << " " << w.y;
        EXPECT_NEAR(s.bounds.extent().x, 1.0, 1e-3);
        EXPECT_NEAR(s.bounds.extent().y, 1.0, 1e-3);
    }
}

TEST_F(Decoders, TruncatedDracoStreamIsAClearMessage) {
    int id = 0;
    Bytes stream = dracoQuad(false, id);
    stream.resize(stream.size() / 2);
    expectError(write("truncated.glb", dracoGlb(stream, id)), "Draco stream (bufferView 0, ");
    expectError(write("truncated.glb", dracoGlb(stream, id)), "cannot be decoded");
}

TEST_F(Decoders, DracoHeaderDeclaringTooManyFacesIsRefusedBeforeDecoding) {
    int id = 0;
    Bytes stream = dracoQuad(true, id);
    // Sequential connectivity: num_faces is the varint right after the 11-byte header; 2 fits one byte.
    ASSERT_EQ(stream[11], 2);
    const Bytes huge = {0xFF, 0xFF, 0xFF, 0xFF, 0x07};  // 2^31 - 1 faces
    stream.erase(stream.begin() + 11);
    stream.insert(stream.begin() + 11, huge.begin(), huge.end());
    const auto start = std::chrono::steady_clock::now();
    expectError(write("huge.glb", dracoGlb(stream, id)), "exceeds the load limit indices");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 0.5);
}

// The triangle's positions and indices meshopt-encoded into buffer 0; buffer 1 the fallback.
struct MeshoptParts {
    std::string positionsMode = "ATTRIBUTES", indexMode = "TRIANGLES";
    std::uint64_t positionCount = 3;
    bool truncate = false;
};

Bytes meshoptGlb(const MeshoptParts& parts = {}) {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::uint32_t indices[3] = {0, 1, 2};
    Bytes vertexData(meshopt_encodeVertexBufferBound(3, 12));
    vertexData.resize(meshopt_encodeVertexBuffer(vertexData.data(), vertexData.size(), positions, 3, 12));
    Bytes indexData(meshopt_encodeIndexBufferBound(3, 3));
    indexData.resize(meshopt_encodeIndexBuffer(indexData.data(), indexData.size(), indices, 3));
    if (parts.truncate) vertexData.resize(vertexData.size() / 2);
    Bytes bin = vertexData;
    pad4(bin);
    const std::size_t indexOffset = bin.size();
    bin.insert(bin.end(), indexData.begin(), indexData.end());
    pad4(bin);
    auto ext = [](std::size_t offset, std::size_t length, int stride, std::uint64_t count, const std::string& mode) {
        return json{{"EXT_meshopt_compression",
                     {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}, {"byteStride", stride},
                      {"count", count}, {"mode", mode}}}};
    };
    const json j = {
        {"asset", {{"version", "2.0"}}},
        {"extensionsUsed", {"EXT_meshopt_compression"}},
        {"extensionsRequired", {"EXT_meshopt_compression"}},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
          {{"bufferView", 1}, {"componentType", 5125}, {"count", 3}, {"type", "SCALAR"}}}},
        {"bufferViews",
         {{{"buffer", 1}, {"byteLength", 36}, {"byteStride", 12},
           {"extensions", ext(0, vertexData.size(), 12, parts.positionCount, parts.positionsMode)}},
          {{"buffer", 1}, {"byteOffset", 36}, {"byteLength", 12},
           {"extensions", ext(indexOffset, indexData.size(), 4, 3, parts.indexMode)}}}},
        {"buffers",
         {{{"byteLength", bin.size()}},
          {{"byteLength", 48}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}}},
    };
    return glb(j, bin);
}

TEST_F(Decoders, MeshoptTriangleLoadsAsThePlainOne) {
    const Scene s = expectLoads(write("meshopt.glb", meshoptGlb()));
    ASSERT_EQ(s.meshes.size(), 1u);
    ASSERT_EQ(s.meshes[0].primitives.size(), 1u);
    const Primitive& p = s.meshes[0].primitives[0];
    EXPECT_EQ(p.positions, (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
    EXPECT_EQ(p.indices, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST_F(Decoders, MeshoptBadModeIsAClearMessage) {
    MeshoptParts parts;
    parts.positionsMode = "SIDEWAYS";
    expectError(write("mode.glb", meshoptGlb(parts)),
                "bufferView 0: meshopt mode 'SIDEWAYS' is not ATTRIBUTES, TRIANGLES or INDICES");
}

TEST_F(Decoders, MeshoptCorruptDataIsAClearMessage) {
    MeshoptParts parts;
    parts.truncate = true;
    expectError(write("corrupt.glb", meshoptGlb(parts)), "bufferView 0: the meshopt ATTRIBUTES data");
}

TEST_F(Decoders, MeshoptCountPastTheVertexLimitIsRefusedBeforeDecoding) {
    MeshoptParts parts;
    parts.positionCount = 4'000'000'000ull;
    expectError(write("count.glb", meshoptGlb(parts)), "exceeds the load limit vertices");
}

// A textured triangle whose texture's image is named by `textureJson` (images: 0 PNG, 1 `second`).
Bytes textureGlb(const json& textureJson, const Bytes& second, const std::string& secondMime, const json& required) {
    Bytes bin = triangleBin();
    json j = triangleJson("");
    j["images"] = json::array();
    for (const auto& [image, mime] : {std::pair<const Bytes&, std::string>{kPng2x1, "image/png"}, {second, secondMime}}) {
        j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", image.size()}});
        j["images"].push_back({{"bufferView", j["bufferViews"].size() - 1}, {"mimeType", mime}});
        bin.insert(bin.end(), image.begin(), image.end());
        pad4(bin);
    }
    j["buffers"][0]["byteLength"] = bin.size();
    j["textures"] = {textureJson};
    j["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    j["meshes"][0]["primitives"][0]["material"] = 0;
    if (!required.empty()) j["extensionsRequired"] = required;
    return glb(j, bin);
}

Bytes webp2x1() {
    const std::uint8_t rgba[8] = {10, 20, 30, 255, 200, 100, 50, 128};
    std::uint8_t* out = nullptr;
    const std::size_t size = WebPEncodeLosslessRGBA(rgba, 2, 1, 8, &out);
    Bytes bytes(out, out + size);
    WebPFree(out);
    return bytes;
}

TEST_F(Decoders, WebpTextureDecodes) {
    const json texture = {{"source", 0}, {"extensions", {{"EXT_texture_webp", {{"source", 1}}}}}};
    const Scene s = expectLoads(write("webp.glb", textureGlb(texture, webp2x1(), "image/webp", {"EXT_texture_webp"})));
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_EQ(s.textures[0].rgba8, (std::vector<std::uint8_t>{10, 20, 30, 255, 200, 100, 50, 128}));
}

// A lossless WebP header declaring 16384 x 16384 over a few bytes: refused from the header.
TEST_F(Decoders, WebpBombStopsAtTheTextureBudget) {
    Bytes webp = {'R', 'I', 'F', 'F', 0, 0, 0, 0, 'W', 'E', 'B', 'P', 'V', 'P', '8', 'L', 0, 0, 0, 0, 0x2F};
    const std::uint32_t bits = 16383u | (16383u << 14) | (1u << 28);  // width-1, height-1, alpha, version 0
    append(webp, bits);
    webp.resize(webp.size() + 32, 0);
    const std::uint32_t chunk = std::uint32_t(webp.size() - 20), riff = std::uint32_t(webp.size() - 8);
    std::memcpy(webp.data() + 16, &chunk, 4);
    std::memcpy(webp.data() + 4, &riff, 4);
    const json texture = {{"extensions", {{"EXT_texture_webp", {{"source", 1}}}}}};
    const fs::path file = write("bomb.glb", textureGlb(texture, webp, "image/webp", {"EXT_texture_webp"}));
    const LoadResult r = loadScene(file);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_TRUE(r.scene->textures.empty());
    ASSERT_FALSE(r.warnings.empty());
    EXPECT_NE(r.warnings.back().find("(16384x16384) exceeds the load limit texturePixels"), std::string::npos)
        << r.warnings.back();
}

TEST_F(Decoders, RequiredKtx2IsRefusedNamingTheMissingDecoder) {
    const json texture = {{"extensions", {{"KHR_texture_basisu", {{"source", 1}}}}}};
    expectError(write("ktx.glb", textureGlb(texture, Bytes(64, 0), "image/ktx2", {"KHR_texture_basisu"})),
                "requires KHR_texture_basisu (KTX2 / Basis Universal textures), and this build has no Basis Universal "
                "decoder");
}

TEST_F(Decoders, UsedKtx2FallsBackToTheFactorOrThePngSource) {
    const json onlyKtx = {{"extensions", {{"KHR_texture_basisu", {{"source", 1}}}}}};
    const LoadResult factor = loadScene(write("ktx.glb", textureGlb(onlyKtx, Bytes(64, 0), "image/ktx2", {})));
    ASSERT_TRUE(factor.ok()) << factor.error;
    EXPECT_TRUE(factor.scene->textures.empty());
    EXPECT_EQ(factor.scene->materials[0].baseColorTexture, -1);
    ASSERT_FALSE(factor.warnings.empty());
    EXPECT_NE(factor.warnings.back().find("uses its base colour factor"), std::string::npos) << factor.warnings.back();

    const json withPng = {{"source", 0}, {"extensions", {{"KHR_texture_basisu", {{"source", 1}}}}}};
    const LoadResult png = loadScene(write("ktx_png.glb", textureGlb(withPng, Bytes(64, 0), "image/ktx2", {})));
    ASSERT_TRUE(png.ok()) << png.error;
    ASSERT_EQ(png.scene->textures.size(), 1u);
    EXPECT_EQ(png.scene->textures[0].width, 2);
}

TEST_F(Decoders, SeveralScenesOpenTheDefaultOrTheChosenOne) {
    json j = triangleJson();
    j["nodes"].push_back({{"mesh", 0}, {"translation", {10, 0, 0}}, {"name", "Moved"}});
    j["scenes"] = {{{"nodes", {0}}, {"name", "first"}}, {{"nodes", {1}}, {"name", "second"}}};
    j["scene"] = 1;
    const fs::path file = writeGltf(j);
    const Scene byDefault = expectLoads(file);
    EXPECT_EQ(byDefault.shownScene, 1);
    EXPECT_EQ(byDefault.sceneNames, (std::vector<std::string>{"first", "second"}));
    EXPECT_NEAR(byDefault.bounds.min.x, 10.0, 1e-9);
    LoadOptions first;
    first.sceneIndex = 0;
    const Scene chosen = expectLoads(file, first);
    EXPECT_EQ(chosen.shownScene, 0);
    EXPECT_NEAR(chosen.bounds.min.x, 0.0, 1e-9);
    LoadOptions beyond;
    beyond.sceneIndex = 2;
    expectError(file, "scene.index 2 asked for, but the file has 2 scene(s)", beyond);
}

}  // namespace
}  // namespace shadowlab
