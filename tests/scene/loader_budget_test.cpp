// Hostile files (built tiny in memory): every one is refused or defused from its declared counts
// and image headers, never by allocating first. Without the budgets the loader would either load
// the file (after gigabytes and a minute) or report a decode error instead of the budget's warning.
#include "gltf_fixture.h"
#include "scenes/gltf_loader.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <array>
#include <future>
#include <thread>

namespace shadowlab {
namespace {

using namespace testing_files;

class Budgets : public LoaderFiles {};

// One accessor without a bufferView (all zeros by the glTF spec), 4,194,304 VEC3, referenced by 40
// primitives: 168M vertices from a 2 KB file.
json amplificationJson(int primitives) {
    json j = triangleJson("");
    j.erase("buffers");
    j.erase("bufferViews");
    j["accessors"] = {{{"componentType", 5126}, {"count", 4194304}, {"type", "VEC3"}}};
    j["meshes"][0]["primitives"] = json::array();
    for (int i = 0; i < primitives; ++i) j["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 0}}}});
    return j;
}

TEST_F(Budgets, OneZeroAccessorUnderFortyPrimitivesIsRefusedFromItsDeclaredCount) {
    expectError(write("amplify.gltf", amplificationJson(40).dump()), "167772160 vertices");
    expectError(write("amplify.gltf", amplificationJson(40).dump()), "--limit vertices=N");
}

TEST_F(Budgets, TheVertexLimitIsTheUsersToRaise) {
    LoadOptions options;
    options.limits.vertices = 2;
    expectError(writeGltf(triangleJson()), "load limit vertices = 2", options);
    options.limits.vertices = 3;
    options.limits.indices = 2;
    expectError(writeGltf(triangleJson()), "load limit indices = 2", options);
    options.limits.indices = 3;
    expectLoads(writeGltf(triangleJson()), options);
}

TEST_F(Budgets, StripsAreChargedForTheirExpandedIndices) {
    // A strip of 5 indices becomes 3 triangles = 9 list indices.
    json j = triangleJson("");
    j["accessors"][0]["count"] = 5;
    j["meshes"][0]["primitives"][0].erase("indices");
    j["meshes"][0]["primitives"][0]["mode"] = 5;
    j["bufferViews"][0]["byteLength"] = 60;
    j["buffers"][0]["byteLength"] = 60;
    Bytes bin(60, 0);
    LoadOptions options;
    options.limits.indices = 8;
    expectError(write("strip.glb", glb(j, bin)), "9 triangle indices", options);
    options.limits.indices = 9;
    expectLoads(write("strip.glb", glb(j, bin)), options);
}

TEST_F(Budgets, PrimitivesSharingAnAccessorGetEqualGeometry) {
    json j = triangleJson();
    j["meshes"][0]["primitives"].push_back(j["meshes"][0]["primitives"][0]);
    j["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 0}}}});
    const Scene s = expectLoads(writeGltf(j));
    ASSERT_EQ(s.meshes[0].primitives.size(), 3u);
    for (const Primitive& p : s.meshes[0].primitives) {
        EXPECT_EQ(p.positions, s.meshes[0].primitives[0].positions);
        EXPECT_EQ(p.normals, s.meshes[0].primitives[0].normals);
        EXPECT_EQ(p.indices, (std::vector<std::uint32_t>{0, 1, 2}));
    }
}

json instancedJson(int nodes) {
    json j = triangleJson();
    j["nodes"] = json::array();
    j["scenes"][0]["nodes"] = json::array();
    for (int i = 0; i < nodes; ++i) {
        j["nodes"].push_back({{"mesh", 0}, {"translation", {i, 0, 0}}});
        j["scenes"][0]["nodes"].push_back(i);
    }
    return j;
}

TEST_F(Budgets, InstancesAndDrawnTrianglesAreCountedAfterFlattening) {
    LoadOptions options;
    options.limits.instances = 4;
    expectError(writeGltf(instancedJson(5)), "5 mesh instances, which exceeds the load limit instances = 4", options);
    expectLoads(writeGltf(instancedJson(4)), options);
    options.limits.drawnTriangles = 3;
    expectError(writeGltf(instancedJson(4)), "load limit drawnTriangles = 3", options);
}

TEST_F(Budgets, NodesArrayIsLimitedBeforeTinygltfMaterialisesIt) {
    LoadOptions options;
    options.limits.nodes = 4;
    options.limits.instances = 100;
    expectError(writeGltf(instancedJson(5)), "5 nodes exceeds the load limit nodes = 4", options);
}

TEST_F(Budgets, DeepJsonIsRefusedBeforeParsing) {
    // 100,000 nested arrays in "extras": a recursive consumer would run out of stack.
    std::string deep = triangleJson().dump();
    deep.pop_back();
    deep += ",\"extras\":" + std::string(100000, '[') + std::string(100000, ']') + "}";
    expectError(write("deep.gltf", deep), "JSON nesting depth exceeds the load limit jsonDepth = 64");
    // Brackets inside strings do not count.
    json j = triangleJson();
    j["extras"] = std::string(1000, '[');
    write("tri.bin", triangleBin());
    expectLoads(write("strings.gltf", j.dump()));
}

TEST_F(Budgets, JsonSizeAndFileSizeAreLimited) {
    LoadOptions options;
    options.limits.jsonBytes = 100;
    expectError(writeGltf(triangleJson()), "exceeds the load limit jsonBytes = 100", options);
    options.limits.fileBytes = 100;
    expectError(write("tri.glb", glb(triangleJson(""), triangleBin())), "exceeds the load limit fileBytes = 100", options);
}

TEST_F(Budgets, AnimationKeysAreLimitedFromDeclaredCounts) {
    json j = triangleJson();
    j["accessors"].push_back({{"componentType", 5126}, {"count", 4194304}, {"type", "SCALAR"}});
    j["accessors"].push_back({{"componentType", 5126}, {"count", 4194304}, {"type", "VEC3"}});
    json channels = json::array();
    for (int i = 0; i < 10; ++i) channels.push_back({{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}});
    j["animations"] = {{{"samplers", {{{"input", 2}, {"output", 3}}}}, {"channels", channels}}};
    expectError(writeGltf(j), "exceeds the load limit animationKeys");
}

// A PNG whose header says side x side (1-bit grey) with almost no pixel data: the header is all
// a size check may read; decoding it would fail, so a loader that decodes first reports an error.
Bytes pngHeaderOnly(std::uint32_t side) {
    return pngFile(pngHeader(side, side, 1, 0), {0x78, 0x01, 0x01, 0x00, 0x00, 0xFF, 0xFF});
}

std::size_t countContaining(const std::vector<std::string>& lines, const std::string& part) {
    return std::size_t(std::count_if(lines.begin(), lines.end(),
                                     [&](const std::string& l) { return l.find(part) != std::string::npos; }));
}

TEST_F(Budgets, FourHugePngsAreSkippedFromTheirHeadersWithoutDecoding) {
    const Bytes big = pngHeaderOnly(16384);
    ASSERT_LT(big.size(), 200u);
    const LoadResult r = loadScene(write("bomb.glb", texturedGlb({big, big, big, big}, {0, 1, 2, 3})));
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(countContaining(r.warnings, "(16384x16384) exceeds the load limit texturePixels"), 4u);
    EXPECT_TRUE(r.scene->textures.empty());
    for (const Material& m : r.scene->materials) EXPECT_EQ(m.baseColorTexture, -1);  // the factor is used
}

TEST_F(Budgets, OneHugePngSharedByEightTexturesIsLookedAtOnce) {
    const LoadResult r = loadScene(write("shared.glb", texturedGlb({pngHeaderOnly(16384)}, {0, 0, 0, 0, 0, 0, 0, 0})));
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(countContaining(r.warnings, "texturePixels"), 1u);
    EXPECT_TRUE(r.scene->textures.empty());
}

TEST_F(Budgets, TexturesSharingAnImageAndSamplerAreDecodedOnce) {
    const Scene s = expectLoads(write("shared.glb", texturedGlb({kPng2x1}, {0, 0, 0})));
    ASSERT_EQ(s.textures.size(), 1u);
    for (const Material& m : s.materials) EXPECT_EQ(m.baseColorTexture, 0);
}

TEST_F(Budgets, TheTotalTextureBudgetSkipsTheImageThatWouldExceedIt) {
    LoadOptions options;
    options.limits.textureBytes = 8;  // one 2x1 RGBA8 image
    const LoadResult r = loadScene(write("two.glb", texturedGlb({kPng2x1, kPng16Gray}, {0, 1})), options);
    ASSERT_TRUE(r.ok()) << r.error;
    ASSERT_EQ(r.scene->textures.size(), 1u);
    EXPECT_EQ(r.scene->materials[0].baseColorTexture, 0);
    EXPECT_EQ(r.scene->materials[1].baseColorTexture, -1);
    EXPECT_EQ(countContaining(r.warnings, "exceeds the load limit textureBytes = 8"), 1u);
}

TEST_F(Budgets, StbsOwnReasonIsKeptForAnUndecodableImage) {
    Bytes broken = kPng2x1;
    broken.resize(40);  // header intact, pixel data cut off
    const LoadResult r = loadScene(write("cut.glb", texturedGlb({broken}, {0})));
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error.find("image 0 cannot be decoded ("), std::string::npos) << r.error;
    EXPECT_EQ(r.error.find("Unknown image format"), std::string::npos) << r.error;
}

TEST_F(Budgets, HeadersOnlyGivesSizesWithoutPixelsAndDeferredDecodesLater) {
    const fs::path file = write("img.glb", texturedGlb({kPng2x1}, {0}));
    LoadOptions options;
    options.textures = TextureDecoding::HeadersOnly;
    const Scene headers = expectLoads(file, options);
    ASSERT_EQ(headers.textures.size(), 1u);
    EXPECT_EQ(headers.textures[0].width, 2);
    EXPECT_EQ(headers.textures[0].height, 1);
    EXPECT_TRUE(headers.textures[0].rgba8.empty());
    EXPECT_FALSE(headers.textures[0].encoded);

    options.textures = TextureDecoding::Deferred;
    Scene deferred = expectLoads(file, options);
    ASSERT_TRUE(deferred.textures[0].encoded);
    EXPECT_TRUE(deferred.textures[0].rgba8.empty());
    std::string error;
    ASSERT_TRUE(decodeTexture(deferred.textures[0], error)) << error;
    EXPECT_FALSE(deferred.textures[0].encoded);
    EXPECT_EQ(deferred.textures[0].rgba8, expectLoads(file).textures[0].rgba8);
    EXPECT_FALSE(decodeTexture(deferred.textures[0], error));  // nothing left to decode
}

TEST_F(Budgets, FifosAndDevicesAreRefusedWithoutBlocking) {
    const fs::path fifo = dir / "fifo.gltf";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    expectError(fifo, "not a regular file");  // blocked forever before: open() of a FIFO without a writer
    expectError("/dev/urandom", "not a regular file");
    // An image file that is a FIFO: tinygltf's blocking read would hang on it.
    ASSERT_EQ(::mkfifo((dir / "fifo.png").c_str(), 0600), 0);
    expectError(writeGltf(withTexture(triangleJson(), {{"uri", "fifo.png"}})), "is not a regular file");
}

TEST_F(Budgets, LongNamesAreCutInMessages) {
    json j = triangleJson();
    j["nodes"][0]["name"] = std::string(1 << 20, 'x');
    j["nodes"][0]["scale"] = {1, 2};
    const LoadResult r = loadScene(writeGltf(j));
    ASSERT_FALSE(r.ok());
    EXPECT_LT(r.error.size(), 400u);
    EXPECT_NE(r.error.find("scale must be 3 finite numbers"), std::string::npos);
}

TEST_F(Budgets, JsonErrorsGiveLineAndColumn) {
    expectError(write("broken.gltf", std::string("{\n  \"asset\": {\n    \"version\": ]\n")), "line 3, column 16");
}

TEST_F(Budgets, LoadingOnSeveralThreadsAtOnceGivesTheSameScene) {
    const fs::path file = write("img.glb", texturedGlb({kPng2x1, kPng16Gray}, {0, 1, 0}));
    std::array<std::future<LoadResult>, 4> loads;
    for (auto& load : loads) load = std::async(std::launch::async, [&] { return loadScene(file); });
    const LoadResult first = loadScene(file);
    ASSERT_TRUE(first.ok()) << first.error;
    for (auto& load : loads) {
        const LoadResult r = load.get();
        ASSERT_TRUE(r.ok()) << r.error;
        ASSERT_EQ(r.scene->textures.size(), first.scene->textures.size());
        for (std::size_t t = 0; t < r.scene->textures.size(); ++t)
            EXPECT_EQ(r.scene->textures[t].rgba8, first.scene->textures[t].rgba8);
        EXPECT_EQ(r.scene->meshes[0].primitives[0].positions, first.scene->meshes[0].primitives[0].positions);
    }
}

TEST(LoadLimits, ParsedFromKeyEqualsValueWithoutUndefinedConversions) {
    LoadLimits limits;
    std::string error;
    EXPECT_TRUE(setLoadLimit(limits, "vertices=64e6", error)) << error;
    EXPECT_EQ(limits.vertices, 64000000u);
    EXPECT_TRUE(setLoadLimit(limits, "textureBytes=4294967296", error)) << error;
    EXPECT_EQ(limits.textureBytes, 4294967296u);
    for (const char* bad : {"vertices=-1", "vertices=nan", "vertices=1e300", "vertices=2.5", "vertices=", "vertices"}) {
        error.clear();
        EXPECT_FALSE(setLoadLimit(limits, bad, error)) << bad;
        EXPECT_FALSE(error.empty());
    }
    EXPECT_FALSE(setLoadLimit(limits, "bogus=1", error));
    EXPECT_NE(error.find("unknown load limit 'bogus'"), std::string::npos) << error;
    EXPECT_EQ(limits.vertices, 64000000u);  // refused values change nothing
}

TEST(LoadLimits, EveryLimitIsListedWithItsValue) {
    const std::vector<std::string> lines = describeLoadLimits(LoadLimits{});
    ASSERT_EQ(lines.size(), 11u);
    EXPECT_NE(countContaining(lines, "vertices = 33554432"), 0u);
    EXPECT_NE(countContaining(lines, "texturePixels = 67108864"), 0u);
    for (const std::string& line : lines) {
        LoadLimits limits;
        std::string error;
        const std::string key = line.substr(0, line.find(' '));
        EXPECT_TRUE(setLoadLimit(limits, key + "=7", error)) << key << ": " << error;
    }
}

}  // namespace
}  // namespace shadowlab
