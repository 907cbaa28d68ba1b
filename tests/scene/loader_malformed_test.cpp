// A malformed corpus written by the tests into a temporary folder: every bad file gives one clear
// message naming the file and the reason, never a crash and never a half-loaded scene. Plus small
// synthetic valid files for the paths the samples do not cover (strips, fans, index widths).
#include "gltf_fixture.h"
#include "scenes/gltf_loader.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <unistd.h>

namespace shadowlab {
namespace {

using namespace testing_files;
namespace fs = std::filesystem;
using json = nlohmann::json;

class Malformed : public LoaderFiles {};

TEST_F(Malformed, TheValidTriangleLoadsInBothContainers) {
    const Scene a = expectLoads(writeGltf(triangleJson()));
    EXPECT_EQ(a.triangleCount(), 1u);
    const Scene b = expectLoads(write("tri.glb", glb(triangleJson(""), triangleBin())));
    EXPECT_EQ(b.triangleCount(), 1u);
    EXPECT_EQ(a.meshes[0].primitives[0].positions, b.meshes[0].primitives[0].positions);
}

// A GLB whose BIN chunk is large (4 MB and more, larger than its JSON) is handed to tinygltf without
// the chunk's copy (scenes/gltf_glb_bin.cpp): the same scene as from a small GLB, and for a buffer
// that does not fit the chunk, tinygltf's own refusal as before.
TEST_F(Malformed, LargeGlbBinChunkLoadsLikeASmallOne) {
    Bytes bin = triangleBin(2, 0.25f);
    bin.resize(std::size_t(5) << 20, 0xAB);  // the triangle, then 5 MB that no view reads
    json j = triangleJson("");
    j["buffers"][0]["byteLength"] = bin.size();
    const Scene large = expectLoads(write("large.glb", glb(j, bin)));
    const Scene small = expectLoads(write("small.glb", glb(triangleJson(""), triangleBin(2, 0.25f))));
    ASSERT_EQ(large.meshes.size(), 1u);
    ASSERT_EQ(large.meshes[0].primitives.size(), 1u);
    EXPECT_EQ(large.meshes[0].primitives[0].positions, small.meshes[0].primitives[0].positions);
    EXPECT_EQ(large.meshes[0].primitives[0].indices, small.meshes[0].primitives[0].indices);
    EXPECT_EQ(large.meshes[0].primitives[0].positions[0].x, 0.25f);

    j["buffers"][0]["byteLength"] = bin.size() + 4;  // more than the chunk holds
    expectError(write("short.glb", glb(j, bin)), "byteLength");
    json second = triangleJson("");
    second["buffers"][0]["byteLength"] = bin.size();
    second["buffers"].push_back({{"byteLength", 4}});  // a second buffer without a URI: tinygltf's path
    EXPECT_EQ(expectLoads(write("two.glb", glb(second, bin))).triangleCount(), 1u);
}

// Normalized uint16 texcoords through KHR_texture_transform are transformed from the exact
// quotient u / 65535 in double (the accessors otherwise decode to float): the fixture is chosen so
// that rounding the quotient to float first would change a result.
TEST_F(Malformed, NormalizedTexcoordsAreTransformedAtFullPrecision) {
    Bytes bin = triangleBin();
    const std::uint16_t raw[6] = {1, 65534, 12345, 54321, 40000, 3};
    for (std::uint16_t v : raw) append(bin, v);
    json j = withTexture(triangleJson(), {{"uri", "tex.png"}});
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 44}, {"byteLength", 12}});
    j["accessors"].push_back(
        {{"bufferView", 2}, {"componentType", 5123}, {"normalized", true}, {"count", 3}, {"type", "VEC2"}});
    j["buffers"][0]["byteLength"] = bin.size();
    j["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 2;
    const double offset[2] = {0.1, 0.2}, scale[2] = {3.7, 1.3}, rotation = 0.3;
    j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"] = {
        {"offset", {offset[0], offset[1]}}, {"scale", {scale[0], scale[1]}}, {"rotation", rotation}};
    write("tex.png", kPng2x1);
    const Scene scene = expectLoads(writeGltf(j, bin));
    ASSERT_EQ(scene.meshes.size(), 1u);
    const std::vector<glm::vec2>& uv = scene.meshes[0].primitives[0].texcoords;
    ASSERT_EQ(uv.size(), 3u);
    const double c = std::cos(rotation), s = std::sin(rotation);
    const glm::dmat3 transform(glm::dvec3(c * scale[0], -s * scale[0], 0.0), glm::dvec3(s * scale[1], c * scale[1], 0.0),
                               glm::dvec3(offset[0], offset[1], 1.0));
    int roundedWouldDiffer = 0;
    for (int i = 0; i < 3; ++i) {
        const glm::dvec2 exact(raw[2 * i] / 65535.0, raw[2 * i + 1] / 65535.0);
        const glm::dvec3 want = transform * glm::dvec3(exact, 1.0);
        EXPECT_EQ(uv[std::size_t(i)], glm::vec2(float(want.x), float(want.y))) << "vertex " << i;
        const glm::dvec3 rounded = transform * glm::dvec3(glm::dvec2(glm::vec2(exact)), 1.0);
        roundedWouldDiffer += glm::vec2(float(rounded.x), float(rounded.y)) != glm::vec2(float(want.x), float(want.y));
    }
    EXPECT_GT(roundedWouldDiffer, 0) << "the fixture does not tell a float-first decode apart";
}

TEST_F(Malformed, MissingFile) { expectError(dir / "nothere.gltf", "file not found"); }

TEST_F(Malformed, EmptyFile) { expectError(write("empty.gltf", std::string()), "empty"); }

TEST_F(Malformed, NotJsonAtAll) { expectError(write("text.gltf", std::string("hello, I am not glTF")), "not a glTF file"); }

TEST_F(Malformed, BrokenJson) { expectError(write("broken.gltf", std::string("{ \"asset\": { \"version\": ")), "invalid JSON"); }

TEST_F(Malformed, JsonWithoutAsset) { expectError(write("noasset.gltf", std::string("{\"nodes\": []}")), "asset"); }

TEST_F(Malformed, UnsupportedVersion) {
    json j = triangleJson();
    j["asset"]["version"] = "1.0";
    expectError(writeGltf(j), "version 1.0");
}

TEST_F(Malformed, TruncatedGlb) {
    Bytes whole = glb(triangleJson(""), triangleBin());
    whole.resize(whole.size() / 2);
    expectError(write("half.glb", whole), "truncated GLB");
}

TEST_F(Malformed, TruncatedGlbHeader) {
    Bytes whole = glb(triangleJson(""), triangleBin());
    whole.resize(10);
    expectError(write("header.glb", whole), "truncated GLB");
}

TEST_F(Malformed, GlbMissingItsLastBytes) {
    Bytes whole = glb(triangleJson(""), triangleBin());
    whole.resize(whole.size() - 4);
    expectError(write("short.glb", whole), "truncated GLB");
}

TEST_F(Malformed, GlbExtensionWithoutMagic) { expectError(write("fake.glb", std::string("GLTF0000garbage")), "magic"); }

TEST_F(Malformed, BufferViewBeyondItsBuffer) {
    json j = triangleJson();
    j["bufferViews"][0]["byteOffset"] = 40;
    expectError(writeGltf(j), "out of bounds of buffer");
}

TEST_F(Malformed, AccessorBeyondItsBufferView) {
    json j = triangleJson();
    j["accessors"][0]["count"] = 100;
    expectError(writeGltf(j), "out of bounds of bufferView");
}

TEST_F(Malformed, AccessorWithHugeByteOffset) {
    json j = triangleJson();
    j["accessors"][0]["byteOffset"] = 4000000000LL;
    expectError(writeGltf(j), "out of bounds of bufferView");
}

TEST_F(Malformed, AccessorThatDoesNotExist) {
    json j = triangleJson();
    j["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 9;
    expectError(writeGltf(j), "accessor 9 does not exist");
}

TEST_F(Malformed, PositionOfTheWrongType) {
    json j = triangleJson();
    j["accessors"][0]["type"] = "VEC2";
    expectError(writeGltf(j), "expected VEC3");
}

TEST_F(Malformed, StrideSmallerThanTheElement) {
    json j = triangleJson();
    j["bufferViews"][0]["byteStride"] = 8;
    expectError(writeGltf(j), "byteStride 8");
}

TEST_F(Malformed, IndexBeyondTheVertexCount) {
    expectError(writeGltf(triangleJson(), triangleBin(7)), "index 7");
    expectError(writeGltf(triangleJson(), triangleBin(7)), "out of range");
}

TEST_F(Malformed, NanPositionsSkipThatPrimitiveWithAWarning) {
    json j = triangleJson();
    // A second primitive over the same data but with a NaN first vertex (second buffer).
    Bytes bin = triangleBin();
    const Bytes nanBin = triangleBin(2, std::numeric_limits<float>::quiet_NaN());
    bin.insert(bin.end(), nanBin.begin(), nanBin.end());
    j["buffers"][0]["byteLength"] = bin.size();
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 44}, {"byteLength", 36}});
    j["accessors"].push_back({{"bufferView", 2}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
    j["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 2}}}, {"indices", 1}});
    const fs::path file = writeGltf(j, bin);
    const LoadResult r = loadScene(file);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.scene->triangleCount(), 1u);
    ASSERT_EQ(r.scene->meshes[0].primitives.size(), 1u);
    EXPECT_FALSE(r.scene->bounds.empty());
    bool warned = false;
    for (const std::string& w : r.warnings) warned = warned || w.find("NaN") != std::string::npos;
    EXPECT_TRUE(warned);
    EXPECT_EQ(r.warnings, r.scene->warnings);
}

TEST_F(Malformed, InfinitePositionsToo) {
    const fs::path file = writeGltf(triangleJson(), triangleBin(2, std::numeric_limits<float>::infinity()));
    const LoadResult r = loadScene(file);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.scene->triangleCount(), 0u);
    EXPECT_TRUE(r.scene->meshes[0].primitives.empty());
}

TEST_F(Malformed, MissingExternalBuffer) {
    write("scene.gltf", triangleJson("nothere.bin").dump());
    expectError(dir / "scene.gltf", "buffer 0: external file 'nothere.bin' not found");
}

TEST_F(Malformed, ExternalBufferShorterThanDeclared) {
    json j = triangleJson();
    const Bytes bin = triangleBin();
    expectError(writeGltf(j, Bytes(bin.begin(), bin.begin() + 20)), "'tri.bin' has 20 bytes, but byteLength is 44");
}

TEST_F(Malformed, MissingImage) {
    expectError(writeGltf(withTexture(triangleJson(), {{"uri", "nothere.png"}})), "nothere.png");
}

TEST_F(Malformed, UndecodableImage) {
    write("bad.png", std::string("this is no PNG"));
    expectError(writeGltf(withTexture(triangleJson(), {{"uri", "bad.png"}})), "cannot be decoded");
}

TEST_F(Malformed, ImageBufferViewBeyondItsBuffer) {
    json j = withTexture(triangleJson(""), {{"bufferView", 2}, {"mimeType", "image/png"}});
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 40}, {"byteLength", 4000}});
    expectError(write("img.glb", glb(j, triangleBin())), "out of bounds");
}

TEST_F(Malformed, ValidEmbeddedPngIsExpandedToRgba) {
    json j = withTexture(triangleJson(""), {{"bufferView", 2}, {"mimeType", "image/png"}});
    Bytes bin = triangleBin();
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", kPng2x1.size()}});
    bin.insert(bin.end(), kPng2x1.begin(), kPng2x1.end());
    pad4(bin);
    j["buffers"][0]["byteLength"] = bin.size();
    const Scene s = expectLoads(write("img.glb", glb(j, bin)));
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_EQ(s.textures[0].width, 2);
    EXPECT_EQ(s.textures[0].height, 1);
    ASSERT_EQ(s.textures[0].rgba8.size(), 8u);
    // RGB input: opaque alpha added; red then blue.
    EXPECT_EQ(s.textures[0].rgba8, (std::vector<std::uint8_t>{255, 0, 0, 255, 0, 0, 255, 255}));
}

TEST_F(Malformed, SixteenBitGreyPngBecomesRgba8) {
    write("grey16.png", kPng16Gray);
    const Scene s = expectLoads(writeGltf(withTexture(triangleJson(), {{"uri", "grey16.png"}})));
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_EQ(s.textures[0].rgba8, (std::vector<std::uint8_t>{128, 128, 128, 255, 255, 255, 255, 255}));
}

TEST_F(Malformed, RequiredUnknownExtensionIsRefused) {
    json j = triangleJson();
    j["extensionsUsed"] = {"EXT_lights_image_based"};
    j["extensionsRequired"] = {"EXT_lights_image_based"};
    expectError(writeGltf(j), "requires the unsupported extension EXT_lights_image_based");
}

TEST_F(Malformed, RequiredSupportedExtensionsLoad) {
    json j = triangleJson();
    j["extensionsUsed"] = {"KHR_mesh_quantization", "KHR_texture_transform"};
    j["extensionsRequired"] = {"KHR_mesh_quantization", "KHR_texture_transform"};
    EXPECT_EQ(expectLoads(writeGltf(j)).triangleCount(), 1u);
}

TEST_F(Malformed, NodeCycle) {
    json j = triangleJson();
    j["nodes"] = {{{"mesh", 0}, {"children", {1}}}, {{"children", {0}}}};
    expectError(writeGltf(j), "cycle");
}

TEST_F(Malformed, NodeWithTwoParents) {
    json j = triangleJson();
    j["nodes"] = {{{"children", {2}}}, {{"children", {2}}}, {{"mesh", 0}}};
    j["scenes"][0]["nodes"] = {0, 1};
    expectError(writeGltf(j), "two parents");
}

TEST_F(Malformed, ChildThatDoesNotExist) {
    json j = triangleJson();
    j["nodes"][0]["children"] = {5};
    expectError(writeGltf(j), "child node 5 does not exist");
}

TEST_F(Malformed, NonFiniteNodeTransform) {
    json j = triangleJson();
    j["nodes"][0]["scale"] = {1.0, 1.0};
    expectError(writeGltf(j), "scale must be 3 finite numbers");
}

TEST_F(Malformed, SparseIndexBeyondTheAccessor) {
    json j = triangleJson();
    Bytes bin = triangleBin();
    append(bin, std::uint16_t(9));  // sparse index 9 of a 3-vertex accessor
    pad4(bin);
    for (float f : {5.0f, 5.0f, 5.0f}) append(bin, f);
    j["buffers"][0]["byteLength"] = bin.size();
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 44}, {"byteLength", 2}});
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 12}});
    j["accessors"][0]["sparse"] = {{"count", 1},
                                   {"indices", {{"bufferView", 2}, {"componentType", 5123}}},
                                   {"values", {{"bufferView", 3}}}};
    expectError(writeGltf(j, bin), "sparse: index 9");
}

TEST_F(Malformed, SparseWithoutDenseDataStartsFromZeros) {
    json j = triangleJson();
    Bytes bin = triangleBin();
    append(bin, std::uint16_t(1));
    pad4(bin);
    for (float f : {0.0f, 2.0f, 0.0f}) append(bin, f);
    j["buffers"][0]["byteLength"] = bin.size();
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 44}, {"byteLength", 2}});
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 12}});
    j["accessors"][0].erase("bufferView");
    j["accessors"][0]["sparse"] = {{"count", 1},
                                   {"indices", {{"bufferView", 2}, {"componentType", 5123}}},
                                   {"values", {{"bufferView", 3}}}};
    const Scene s = expectLoads(writeGltf(j, bin));
    ASSERT_EQ(s.meshes[0].primitives.size(), 1u);
    const auto& p = s.meshes[0].primitives[0].positions;
    EXPECT_EQ(p, (std::vector<glm::vec3>{{0, 0, 0}, {0, 2, 0}, {0, 0, 0}}));
}

TEST_F(Malformed, PointsAndLinesAreSkippedWithAWarning) {
    json j = triangleJson();
    j["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 0}}}, {"mode", 0}});
    j["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 0}}}, {"mode", 1}});
    const Scene s = expectLoads(writeGltf(j));
    EXPECT_EQ(s.meshes[0].primitives.size(), 1u);
    int warned = 0;
    for (const std::string& w : s.warnings) warned += w.find("points/lines") != std::string::npos;
    EXPECT_EQ(warned, 2);
}

TEST_F(Malformed, StripsAndFansBecomeListsWithGltfWinding) {
    // 4 vertices of a unit quad; strip 0-1-2-3 and fan 0-1-2-3, non-indexed.
    Bytes bin;
    for (float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 1.f, 1.f, 0.f}) append(bin, f);
    json j = triangleJson();
    j["buffers"][0]["byteLength"] = bin.size();
    j["bufferViews"] = {{{"buffer", 0}, {"byteLength", 48}}};
    j["accessors"] = {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}}};
    j["meshes"][0]["primitives"] = {{{"attributes", {{"POSITION", 0}}}, {"mode", 5}},
                                    {{"attributes", {{"POSITION", 0}}}, {"mode", 6}}};
    const Scene s = expectLoads(writeGltf(j, bin));
    ASSERT_EQ(s.meshes[0].primitives.size(), 2u);
    EXPECT_EQ(s.meshes[0].primitives[0].indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2}));
    EXPECT_EQ(s.meshes[0].primitives[1].indices, (std::vector<std::uint32_t>{1, 2, 0, 2, 3, 0}));
    // Both strip triangles of the quad face +z (consistent winding).
    for (const glm::vec3& n : s.meshes[0].primitives[0].normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f);
}

TEST_F(Malformed, UnsignedByteAndIntIndices) {
    for (int componentType : {5121, 5125}) {
        SCOPED_TRACE(componentType);
        Bytes bin;
        for (float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) append(bin, f);
        for (std::uint32_t i : {2u, 1u, 0u}) {
            if (componentType == 5121) append(bin, std::uint8_t(i));
            else append(bin, i);
        }
        pad4(bin);
        json j = triangleJson();
        j["buffers"][0]["byteLength"] = bin.size();
        j["bufferViews"][1]["byteLength"] = componentType == 5121 ? 3 : 12;
        j["accessors"][1]["componentType"] = componentType;
        const Scene s = expectLoads(writeGltf(j, bin));
        EXPECT_EQ(s.meshes[0].primitives[0].indices, (std::vector<std::uint32_t>{2, 1, 0}));
    }
}

TEST_F(Malformed, FloatIndicesAreRefused) {
    json j = triangleJson();
    j["accessors"][1]["componentType"] = 5126;
    expectError(writeGltf(j), "not an unsigned integer type");
}

TEST_F(Malformed, MaterialThatDoesNotExist) {
    json j = triangleJson();
    j["meshes"][0]["primitives"][0]["material"] = 3;
    expectError(writeGltf(j), "material 3 does not exist");
}

TEST_F(Malformed, LightThatDoesNotExist) {
    json j = triangleJson();
    j["extensionsUsed"] = {"KHR_lights_punctual"};
    j["extensions"] = {{"KHR_lights_punctual", {{"lights", {{{"type", "directional"}}}}}}};
    j["nodes"][0]["extensions"] = {{"KHR_lights_punctual", {{"light", 4}}}};
    expectError(writeGltf(j), "light 4 does not exist");
}

TEST_F(Malformed, SpotAndDirectionalLightsArePlacedByTheirNodes) {
    json j = triangleJson();
    j["extensionsUsed"] = {"KHR_lights_punctual"};
    j["extensions"] = {{"KHR_lights_punctual",
                        {{"lights",
                          {{{"type", "directional"}, {"name", "sun"}},
                           {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}}}}}}};
    // Node 1 rotates by -90 degrees about x, which turns the light's -Z into -Y (straight down).
    const double h = std::sqrt(0.5);
    j["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"rotation", {-h, 0, 0, h}}});
    j["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}, {"translation", {1, 2, 3}}});
    j["scenes"][0]["nodes"] = {0, 1, 2};
    const Scene s = expectLoads(writeGltf(j));
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_FALSE(s.defaultLight);
    EXPECT_EQ(s.lights[0].type, LightType::Directional);
    EXPECT_NEAR(s.lights[0].direction.y, -1.0, 1e-9);
    EXPECT_EQ(s.lights[1].type, LightType::Spot);
    EXPECT_FLOAT_EQ(s.lights[1].outerConeAngle, 0.5f);
    EXPECT_EQ(s.lights[1].position, glm::dvec3(1, 2, 3));
    EXPECT_NEAR(s.lights[1].direction.z, -1.0, 1e-12);
}

TEST_F(Malformed, CubicSplineAnimationNeedsThreeValuesPerKey) {
    json j = triangleJson();
    Bytes bin = triangleBin();
    for (float t : {0.f, 1.f}) append(bin, t);
    for (int k = 0; k < 4; ++k)  // 4 vec3: wrong (cubic spline needs 6 for 2 keys)
        for (float f : {0.f, 1.f, 2.f}) append(bin, f);
    j["buffers"][0]["byteLength"] = bin.size();
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 44}, {"byteLength", 8}});
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 52}, {"byteLength", 48}});
    j["accessors"].push_back({{"bufferView", 2}, {"componentType", 5126}, {"count", 2}, {"type", "SCALAR"}});
    j["accessors"].push_back({{"bufferView", 3}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}});
    j["animations"] = {{{"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}},
                        {"samplers", {{{"input", 2}, {"output", 3}, {"interpolation", "CUBICSPLINE"}}}}}};
    expectError(writeGltf(j, bin), "expected 6");
    j["animations"][0]["samplers"][0]["interpolation"] = "STEP";
    j["accessors"][3]["count"] = 2;
    const Scene s = expectLoads(writeGltf(j, bin));
    ASSERT_EQ(s.animations.size(), 1u);
    EXPECT_EQ(s.animations[0].channels[0].interpolation, Interpolation::Step);
    EXPECT_FLOAT_EQ(s.animations[0].duration, 1.0f);
}

TEST_F(Malformed, InfiniteFarPlaneBecomesFiniteFromTheBounds) {
    json j = triangleJson();
    j["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.05}}}}};  // no zfar
    j["nodes"].push_back({{"camera", 0}, {"translation", {0, 0, 10}}});
    j["scenes"][0]["nodes"] = {0, 1};
    const Scene s = expectLoads(writeGltf(j));
    ASSERT_EQ(s.cameras.size(), 1u);
    EXPECT_FALSE(s.defaultCamera);
    const Camera& c = s.cameras[0];
    EXPECT_TRUE(std::isfinite(c.zfar));
    const double farthest = glm::length(glm::dvec3(c.cameraToWorld[3]) - s.bounds.center()) +
                            0.5 * glm::length(s.bounds.extent());
    EXPECT_GE(double(c.zfar), farthest);
    EXPECT_LT(double(c.zfar), 10.0 * farthest);
}

// Every prefix of a valid GLB, and random byte corruptions of it, load or fail cleanly.
TEST_F(Malformed, TruncationsAndCorruptionsNeverCrash) {
    json j = withTexture(triangleJson(""), {{"bufferView", 2}, {"mimeType", "image/png"}});
    Bytes bin = triangleBin();
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", kPng2x1.size()}});
    bin.insert(bin.end(), kPng2x1.begin(), kPng2x1.end());
    pad4(bin);
    j["buffers"][0]["byteLength"] = bin.size();
    const Bytes valid = glb(j, bin);
    ASSERT_TRUE(loadScene(write("valid.glb", valid)).ok());

    int failures = 0;
    for (std::size_t size = 0; size < valid.size(); size += 3) {
        const fs::path file = write("cut.glb", Bytes(valid.begin(), valid.begin() + long(size)));
        const LoadResult r = loadScene(file);
        EXPECT_FALSE(r.ok()) << "prefix of " << size << " bytes loaded";
        EXPECT_EQ(r.error.rfind(file.string() + ": ", 0), 0u) << r.error;
        failures += !r.ok();
    }
    EXPECT_GT(failures, 0);

    std::mt19937 rng(1234);
    for (int round = 0; round < 300; ++round) {
        Bytes bytes = valid;
        const int flips = 1 + int(rng() % 4);
        for (int f = 0; f < flips; ++f) bytes[rng() % bytes.size()] = static_cast<unsigned char>(rng());
        const fs::path file = write("fuzz.glb", bytes);
        const LoadResult r = loadScene(file);
        if (r.ok()) {
            EXPECT_TRUE(r.error.empty());
        } else {
            EXPECT_EQ(r.error.rfind(file.string() + ": ", 0), 0u) << r.error;
            EXPECT_GT(r.error.size(), file.string().size() + 2);
        }
    }
}

}  // namespace
}  // namespace shadowlab
