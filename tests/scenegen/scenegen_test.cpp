// The generated scenes: deterministic bytes, the documented counts and bounds (scenes/README.md),
// valid geometry, and the situations each scene is there to reproduce.
#include "gltf_inspect.h"
#include "scenes/generators/scene_generators.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <set>

namespace shadowlab::test {
namespace {

namespace fs = std::filesystem;
using scenegen::GenerateOptions;
using scenegen::GenerateResult;
using scenegen::generateScene;

constexpr double kPi = std::numbers::pi;

fs::path tempDir() {
    // One folder per process: CTest runs these tests in parallel processes (-j), and other
    // builds may run them at the same time, so a shared folder would race on the same files.
    const fs::path dir = fs::path(::testing::TempDir()) / ("shadowlab_scenegen_tests_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    // Removed when the test process ends.
    static const struct Cleanup {
        fs::path path;
        ~Cleanup() {
            std::error_code ignored;
            fs::remove_all(path, ignored);
        }
    } cleanup{dir};
    return dir;
}

// Each default scene (seed 1, scale 1) is generated and read back once for the whole suite.
struct Generated {
    GenerateResult result;
    fs::path file;
    Inspected file_;
};

const Generated& defaultScene(const std::string& name) {
    static std::map<std::string, Generated> cache;
    auto it = cache.find(name);
    if (it != cache.end()) return it->second;
    Generated g;
    g.file = tempDir() / (name + ".glb");
    g.result = generateScene(name, GenerateOptions{}, g.file);
    if (g.result.ok) g.file_ = inspect(g.file);
    return cache.emplace(name, std::move(g)).first->second;
}

// The numbers scenes/README.md documents for seed 1, scale 1.
struct Documented {
    std::string name;
    std::size_t nodes, meshInstances, triangles, meshes, materials, cameras, lights;
    glm::dvec3 lo, hi;  // bounds, to 1 cm
};

const std::vector<Documented>& documented() {
    static const std::vector<Documented> d = {
        // name, nodes, mesh instances, triangles drawn, meshes, materials, cameras, lights, bounds
        {"forest", 10008, 10001, 2037960, 7, 9, 5, 1, {-256.23, -14.14, -256.68}, {256.03, 24.88, 256.58}},
        {"cubes", 3005, 3001, 68768, 4, 4, 2, 1, {-120.0, -8.23, -120.0}, {120.0, 10.49, 120.0}},
        {"chessboard", 39, 34, 18014, 14, 6, 3, 1, {-20.0, 0.0, -20.0}, {20.0, 2.3, 20.0}},
        {"street", 571, 564, 13868, 13, 14, 3, 1, {-120.0, 0.0, -1060.0}, {120.0, 79.35, 1060.0}},
        {"plane-box", 4, 2, 14, 2, 2, 1, 1, {-10.0, 0.0, -10.0}, {10.0, 2.0, 10.0}},
        {"interior", 12, 7, 546, 4, 5, 3, 1, {-3.0, 0.0, -2.5}, {3.0, 2.7, 2.5}},
    };
    return d;
}

class EveryScene : public ::testing::TestWithParam<std::string> {};

TEST(SceneGenerators, NamesAreTheSixDocumentedScenesInOrder) {
    EXPECT_EQ(scenegen::generatorNames(),
              (std::vector<std::string>{"forest", "cubes", "chessboard", "street", "plane-box", "interior"}));
    EXPECT_EQ(scenegen::generatorNameList(), "forest, cubes, chessboard, street, plane-box, interior");
}

TEST_P(EveryScene, SameSeedGivesByteIdenticalFiles) {
    const Generated& first = defaultScene(GetParam());
    ASSERT_TRUE(first.result.ok) << first.result.error;
    const fs::path again = tempDir() / (GetParam() + "-again.glb");
    const GenerateResult second = generateScene(GetParam(), GenerateOptions{}, again);
    ASSERT_TRUE(second.ok) << second.error;
    const std::string a = readBytes(first.file), b = readBytes(again);
    EXPECT_GT(a.size(), 1000u);
    EXPECT_TRUE(a == b) << "two runs with seed 1 differ";
}

TEST_P(EveryScene, CountsAndBoundsAreTheDocumentedOnes) {
    const Generated& g = defaultScene(GetParam());
    ASSERT_TRUE(g.result.ok) << g.result.error;
    ASSERT_TRUE(g.file_.error.empty()) << g.file_.error;
    const Inspected& f = g.file_;
    const auto doc = std::find_if(documented().begin(), documented().end(), [&](const Documented& d) { return d.name == GetParam(); });
    ASSERT_NE(doc, documented().end());
    // What the file holds, counted by tinygltf and this test...
    EXPECT_EQ(f.model.nodes.size(), doc->nodes);
    EXPECT_EQ(f.nodes.size(), doc->nodes) << "every node is reachable from the scene";
    EXPECT_EQ(f.meshInstances, doc->meshInstances);
    EXPECT_EQ(f.triangles, doc->triangles);
    EXPECT_EQ(f.model.meshes.size(), doc->meshes);
    EXPECT_EQ(f.model.materials.size(), doc->materials);
    EXPECT_EQ(f.model.cameras.size(), doc->cameras);
    EXPECT_EQ(f.model.lights.size(), doc->lights);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(f.lo[i], doc->lo[i], 0.01) << "axis " << i;
        EXPECT_NEAR(f.hi[i], doc->hi[i], 0.01) << "axis " << i;
    }
    // ... and what the generator says it wrote.
    const scenegen::SceneStats& s = g.result.stats;
    EXPECT_EQ(s.nodes, f.model.nodes.size());
    EXPECT_EQ(s.meshInstances, f.meshInstances);
    EXPECT_EQ(s.triangles, f.triangles);
    EXPECT_EQ(s.meshes, f.model.meshes.size());
    EXPECT_EQ(s.cameras, f.model.cameras.size());
    EXPECT_EQ(s.lights, f.model.lights.size());
    EXPECT_EQ(s.fileBytes, fs::file_size(g.file));
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(s.boundsMin[i], f.lo[i], 1e-4);
        EXPECT_NEAR(s.boundsMax[i], f.hi[i], 1e-4);
    }
}

TEST_P(EveryScene, EverythingHasAReadableUniqueName) {
    const Generated& g = defaultScene(GetParam());
    ASSERT_TRUE(g.result.ok) << g.result.error;
    const tinygltf::Model& m = g.file_.model;
    auto checkNames = [](const auto& items, const char* what) {
        std::set<std::string> seen;
        for (const auto& item : items) {
            EXPECT_FALSE(item.name.empty()) << "unnamed " << what;
            EXPECT_TRUE(std::all_of(item.name.begin(), item.name.end(), [](char c) { return std::isalnum((unsigned char)c) || c == '_' || c == '-'; }))
                << what << " " << item.name;
            EXPECT_TRUE(seen.insert(item.name).second) << "duplicate " << what << " name " << item.name;
        }
    };
    checkNames(m.materials, "material");
    checkNames(m.meshes, "mesh");
    checkNames(m.cameras, "camera");
    checkNames(m.lights, "light");
    // Node names repeat only where a light or camera node carries its light's / camera's name.
    std::set<std::string> nodeNames;
    for (const tinygltf::Node& n : m.nodes) {
        EXPECT_FALSE(n.name.empty());
        EXPECT_TRUE(nodeNames.insert(n.name).second) << "duplicate node name " << n.name;
    }
}

TEST_P(EveryScene, GeometryIsValidGltfWithOutwardNormals) {
    const Generated& g = defaultScene(GetParam());
    ASSERT_TRUE(g.result.ok) << g.result.error;
    const tinygltf::Model& m = g.file_.model;
    EXPECT_EQ(m.asset.version, "2.0");
    EXPECT_TRUE(std::find(m.extensionsUsed.begin(), m.extensionsUsed.end(), "KHR_lights_punctual") != m.extensionsUsed.end());
    EXPECT_TRUE(m.extensionsRequired.empty());
    EXPECT_EQ(m.buffers.size(), 1u);
    EXPECT_TRUE(m.buffers[0].uri.empty()) << "the buffer is the GLB's BIN chunk";
    for (const tinygltf::Mesh& mesh : m.meshes)
        for (const tinygltf::Primitive& p : mesh.primitives) {
            ASSERT_EQ(p.mode, TINYGLTF_MODE_TRIANGLES) << mesh.name;
            ASSERT_TRUE(p.attributes.count("POSITION") && p.attributes.count("NORMAL")) << mesh.name;
            ASSERT_GE(p.material, 0) << mesh.name;
            ASSERT_LT(p.material, int(m.materials.size()));
            const auto positions = readVec3(m, p.attributes.at("POSITION"));
            const auto normals = readVec3(m, p.attributes.at("NORMAL"));
            const auto indices = readIndices(m, p.indices);
            ASSERT_EQ(positions.size(), normals.size());
            ASSERT_EQ(indices.size() % 3, 0u);
            // POSITION min/max are required by glTF and must be the data's.
            const tinygltf::Accessor& pa = m.accessors[std::size_t(p.attributes.at("POSITION"))];
            glm::vec3 lo(1e30f), hi(-1e30f);
            for (const glm::vec3& v : positions) lo = glm::min(lo, v), hi = glm::max(hi, v);
            ASSERT_EQ(pa.minValues.size(), 3u);
            for (int i = 0; i < 3; ++i) {
                EXPECT_FLOAT_EQ(float(pa.minValues[std::size_t(i)]), lo[i]);
                EXPECT_FLOAT_EQ(float(pa.maxValues[std::size_t(i)]), hi[i]);
            }
            for (const glm::vec3& n : normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f) << mesh.name;
            std::size_t inward = 0, degenerate = 0;
            for (std::size_t t = 0; t < indices.size(); t += 3) {
                ASSERT_LT(std::max({indices[t], indices[t + 1], indices[t + 2]}), positions.size());
                const glm::vec3 a = positions[indices[t]], b = positions[indices[t + 1]], c = positions[indices[t + 2]];
                const glm::vec3 face = glm::cross(b - a, c - a);
                if (glm::length(face) < 1e-9f) {
                    ++degenerate;
                    continue;
                }
                // Counter-clockwise front faces: the face normal agrees with the vertex normals.
                if (glm::dot(face, normals[indices[t]] + normals[indices[t + 1]] + normals[indices[t + 2]]) <= 0.0f) ++inward;
            }
            EXPECT_EQ(inward, 0u) << mesh.name << ": triangles wound against their normals";
            EXPECT_EQ(degenerate, 0u) << mesh.name << ": zero-area triangles";
        }
    // Every light is placed by a node, every camera is a perspective camera placed by a node.
    std::set<int> lightsUsed, camerasUsed;
    for (const InspectedNode& n : g.file_.nodes) {
        if (n.light >= 0) lightsUsed.insert(n.light);
        if (n.camera >= 0) camerasUsed.insert(n.camera);
    }
    EXPECT_EQ(lightsUsed.size(), m.lights.size());
    EXPECT_EQ(camerasUsed.size(), m.cameras.size());
    for (const tinygltf::Camera& c : m.cameras) {
        EXPECT_EQ(c.type, "perspective");
        EXPECT_NEAR(c.perspective.yfov, 60.0 * kPi / 180.0, 1e-9) << c.name;
        EXPECT_DOUBLE_EQ(c.perspective.znear, 0.1) << c.name;
        EXPECT_GT(c.perspective.zfar, c.perspective.znear) << c.name;
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, EveryScene,
                         ::testing::Values("forest", "cubes", "chessboard", "street", "plane-box", "interior"),
                         [](const auto& info) {
                             std::string n = info.param;
                             std::replace(n.begin(), n.end(), '-', '_');
                             return n;
                         });

// ---------- options ----------

TEST(SceneGenerators, UnknownNameIsAnErrorListingTheValidNames) {
    const GenerateResult r = generateScene("forrest", {}, tempDir() / "nope.glb");
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("forrest"), std::string::npos);
    EXPECT_NE(r.error.find("forest, cubes, chessboard, street, plane-box, interior"), std::string::npos) << r.error;
    EXPECT_FALSE(fs::exists(tempDir() / "nope.glb"));
}

TEST(SceneGenerators, BadScalesAreErrorsNotCrashes) {
    for (double scale : {0.0, -1.0, 0.001, 17.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
        const GenerateResult r = generateScene("forest", {1, scale}, tempDir() / "bad-scale.glb");
        EXPECT_FALSE(r.ok) << scale;
        EXPECT_NE(r.error.find("--scale"), std::string::npos) << r.error;
    }
    for (const char* fixed : {"plane-box", "chessboard", "interior"}) {
        const GenerateResult r = generateScene(fixed, {1, 2.0}, tempDir() / "fixed.glb");
        EXPECT_FALSE(r.ok) << fixed;
        EXPECT_NE(r.error.find("fixed layout"), std::string::npos) << r.error;
    }
}

TEST(SceneGenerators, OutputProblemsAreErrors) {
    const GenerateResult toFolder = generateScene("plane-box", {}, tempDir());
    EXPECT_FALSE(toFolder.ok);
    EXPECT_NE(toFolder.error.find("folder"), std::string::npos) << toFolder.error;
    const fs::path blocker = tempDir() / "a-file";
    { std::ofstream(blocker) << "x"; }
    const GenerateResult underFile = generateScene("plane-box", {}, blocker / "scene.glb");
    EXPECT_FALSE(underFile.ok);
    EXPECT_FALSE(underFile.error.empty());
    EXPECT_FALSE(generateScene("plane-box", {}, fs::path()).ok);
}

TEST(SceneGenerators, MissingFoldersAreCreatedAndNoPartialFileStays) {
    const fs::path out = tempDir() / "nested" / "deeper" / "plane-box.glb";
    fs::remove_all(tempDir() / "nested");
    const GenerateResult r = generateScene("plane-box", {}, out);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_TRUE(fs::exists(out));
    EXPECT_FALSE(fs::exists(out.string() + ".part"));
}

TEST(SceneGenerators, SeedChangesTheRandomScenes) {
    const std::map<std::string, std::string> groups = {{"forest", "Trees"}, {"cubes", "Cubes"}, {"street", "Buildings"}};
    for (const auto& [name, group] : groups) {
        const fs::path a = tempDir() / (name + "-seed7.glb"), b = tempDir() / (name + "-seed8.glb");
        const GenerateResult ra = generateScene(name, {7, 0.2}, a), rb = generateScene(name, {8, 0.2}, b);
        ASSERT_TRUE(ra.ok && rb.ok) << ra.error << rb.error;
        const Inspected fa = inspect(a, false), fb = inspect(b, false);
        const auto ga = fa.childrenOf(group), gb = fb.childrenOf(group);
        ASSERT_GT(std::min(ga.size(), gb.size()), 10u) << name;
        std::size_t moved = 0;
        for (std::size_t i = 0; i < std::min(ga.size(), gb.size()); ++i)
            if (glm::distance(ga[i]->position(), gb[i]->position()) > 0.01) ++moved;
        EXPECT_GT(moved, std::min(ga.size(), gb.size()) / 2) << name << ": another seed should place most objects elsewhere";
        // Counts of trees and cubes are set by the scale, not the seed.
        if (name != "street") {
            EXPECT_EQ(ga.size(), gb.size()) << name;
        }
    }
    // The fixed layouts do not depend on the seed: only the provenance string in the asset differs.
    for (const char* name : {"plane-box", "chessboard", "interior"}) {
        const fs::path a = tempDir() / (std::string(name) + "-seed7.glb"), b = tempDir() / (std::string(name) + "-seed8.glb");
        ASSERT_TRUE(generateScene(name, {7, 1.0}, a).ok && generateScene(name, {8, 1.0}, b).ok);
        tinygltf::Model ma = inspect(a, false).model, mb = inspect(b, false).model;
        EXPECT_NE(ma.asset.generator, mb.asset.generator);
        ma.asset.generator = mb.asset.generator;
        EXPECT_TRUE(ma == mb) << name;
    }
}

TEST(SceneGenerators, ScaleChangesTheAmountOfContentAtConstantDensity) {
    const GenerateResult small = generateScene("forest", {1, 0.1}, tempDir() / "forest-0.1.glb");
    ASSERT_TRUE(small.ok) << small.error;
    const Inspected f = inspect(tempDir() / "forest-0.1.glb", false);
    EXPECT_EQ(f.childrenOf("Trees").size(), 1000u);
    const double side = small.stats.boundsMax.x - small.stats.boundsMin.x;
    EXPECT_NEAR(side, 512.0 * std::sqrt(0.1), 2.0);

    const GenerateResult twice = generateScene("cubes", {1, 2.0}, tempDir() / "cubes-2.glb");
    ASSERT_TRUE(twice.ok) << twice.error;
    EXPECT_EQ(inspect(tempDir() / "cubes-2.glb", false).childrenOf("Cubes").size(), 6000u);

    const GenerateResult longStreet = generateScene("street", {1, 2.0}, tempDir() / "street-2.glb");
    ASSERT_TRUE(longStreet.ok) << longStreet.error;
    EXPECT_GT(longStreet.stats.boundsMax.z - longStreet.stats.boundsMin.z, 4000.0);
}

// ---------- per scene ----------

// Height of the terrain mesh below (x, z): a vertical ray against the file's triangles.
std::optional<double> groundHeight(const tinygltf::Model& m, int mesh, const glm::dmat4& world, double x, double z) {
    for (const tinygltf::Primitive& p : m.meshes[std::size_t(mesh)].primitives) {
        const auto pos = readVec3(m, p.attributes.at("POSITION"));
        const auto idx = readIndices(m, p.indices);
        for (std::size_t t = 0; t < idx.size(); t += 3) {
            const glm::dvec3 a(world * glm::dvec4(glm::dvec3(pos[idx[t]]), 1.0));
            const glm::dvec3 b(world * glm::dvec4(glm::dvec3(pos[idx[t + 1]]), 1.0));
            const glm::dvec3 c(world * glm::dvec4(glm::dvec3(pos[idx[t + 2]]), 1.0));
            if (std::max({a.x, b.x, c.x}) < x || std::min({a.x, b.x, c.x}) > x) continue;
            if (std::max({a.z, b.z, c.z}) < z || std::min({a.z, b.z, c.z}) > z) continue;
            const double det = (b.z - c.z) * (a.x - c.x) + (c.x - b.x) * (a.z - c.z);
            if (std::abs(det) < 1e-12) continue;
            const double l1 = ((b.z - c.z) * (x - c.x) + (c.x - b.x) * (z - c.z)) / det;
            const double l2 = ((c.z - a.z) * (x - c.x) + (a.x - c.x) * (z - c.z)) / det;
            const double l3 = 1.0 - l1 - l2;
            if (l1 < -1e-9 || l2 < -1e-9 || l3 < -1e-9) continue;
            return l1 * a.y + l2 * b.y + l3 * c.y;
        }
    }
    return std::nullopt;
}

glm::dvec3 lightDirection(const Inspected& f, const std::string& node) {
    const InspectedNode* n = f.node(node);
    return n ? n->forward() : glm::dvec3(0.0);
}

TEST(ForestScene, TenThousandTreesOfSeveralVariantsStandOnTheTerrain) {
    const Generated& g = defaultScene("forest");
    ASSERT_TRUE(g.result.ok) << g.result.error;
    const Inspected& f = g.file_;
    const auto trees = f.childrenOf("Trees");
    ASSERT_EQ(trees.size(), 10000u);
    EXPECT_GE(f.triangles, 1000000u) << "the thesis scene is polygon-rich";
    // Variants: trunk + crown meshes with the documented triangle counts, all of them used.
    const std::map<std::string, std::size_t> variantTriangles = {{"Tree_Spruce", 112}, {"Tree_Pine", 184}, {"Tree_Oak", 308},
                                                                 {"Tree_Birch", 240},  {"Tree_Fir", 112},  {"Tree_Autumn", 212}};
    std::map<int, std::size_t> uses;
    for (const InspectedNode* t : trees) ++uses[t->mesh];
    for (const auto& [name, triangles] : variantTriangles) {
        int mesh = -1;
        for (std::size_t i = 0; i < f.model.meshes.size(); ++i)
            if (f.model.meshes[i].name == name) mesh = int(i);
        ASSERT_GE(mesh, 0) << name;
        EXPECT_EQ(meshTriangles(f.model, mesh), triangles) << name;
        EXPECT_EQ(f.model.meshes[std::size_t(mesh)].primitives.size(), 2u) << name << ": trunk and crown";
        EXPECT_GT(uses[mesh], 500u) << name;
    }
    const InspectedNode* terrain = f.node("Terrain");
    ASSERT_NE(terrain, nullptr);
    EXPECT_EQ(meshTriangles(f.model, terrain->mesh), 2u * 256u * 256u);
    // Every 97th tree: its foot is 0.1 m below the terrain surface right under it (uniform scale).
    for (std::size_t i = 0; i < trees.size(); i += 97) {
        const glm::dvec3 foot = trees[i]->position();
        const auto ground = groundHeight(f.model, terrain->mesh, terrain->world, foot.x, foot.z);
        ASSERT_TRUE(ground.has_value()) << trees[i]->name << " is not above the terrain";
        EXPECT_NEAR(foot.y, *ground - 0.1, 2e-3) << trees[i]->name;
        const glm::dvec3 up = glm::normalize(glm::dvec3(trees[i]->world * glm::dvec4(0, 1, 0, 0)));
        EXPECT_NEAR(up.y, 1.0, 1e-6) << "trees stand upright";
    }
    // Trunks at least 2 m apart (checked on a sample against all).
    for (std::size_t i = 0; i < trees.size(); i += 499)
        for (std::size_t j = 0; j < trees.size(); ++j) {
            if (i == j) continue;
            const glm::dvec3 a = trees[i]->position(), b = trees[j]->position();
            ASSERT_GE(glm::distance(glm::dvec2(a.x, a.z), glm::dvec2(b.x, b.z)), 2.0 - 1e-3);
        }
}

TEST(ForestScene, SunAndThePaperCameraPresets) {
    const Generated& g = defaultScene("forest");
    ASSERT_TRUE(g.result.ok) << g.result.error;
    const Inspected& f = g.file_;
    ASSERT_EQ(f.model.lights.size(), 1u);
    EXPECT_EQ(f.model.lights[0].type, "directional");
    const glm::dvec3 sun = lightDirection(f, "Sun");
    EXPECT_NEAR(std::asin(-sun.y) * 180.0 / kPi, 30.0, 1e-3) << "sun 30 deg above the horizon";
    const glm::dvec3 sunFlat = glm::normalize(glm::dvec3(sun.x, 0, sun.z));

    ASSERT_EQ(f.model.cameras.size(), 5u);
    EXPECT_EQ(f.model.cameras[0].name, "Camera_AlongGround_SunSide") << "the opening view";
    for (const tinygltf::Camera& c : f.model.cameras) {
        EXPECT_DOUBLE_EQ(c.perspective.znear, 0.1);  // thesis ch. 10
        EXPECT_DOUBLE_EQ(c.perspective.zfar, 70.0);
    }
    const InspectedNode* terrain = f.node("Terrain");
    auto eyeHeight = [&](const InspectedNode* cam) {
        const glm::dvec3 e = cam->position();
        return e.y - groundHeight(f.model, terrain->mesh, terrain->world, e.x, e.z).value_or(1e9);
    };
    const InspectedNode* side = f.node("Camera_AlongGround_SunSide");
    const InspectedNode* behind = f.node("Camera_AlongGround_SunBehind");
    const InspectedNode* ahead = f.node("Camera_AlongGround_SunAhead");
    const InspectedNode* alongSun = f.node("Camera_AlongSun");
    ASSERT_TRUE(side && behind && ahead && alongSun && f.node("Camera_Aerial"));
    // LiSPSM's best case: view and light perpendicular in the ground plane, looking along the ground.
    EXPECT_LT(std::abs(glm::dot(glm::normalize(glm::dvec3(side->forward().x, 0, side->forward().z)), sunFlat)), 1e-6);
    EXPECT_LT(std::abs(side->forward().y), std::sin(5.0 * kPi / 180.0));
    // PSM's hard case: the sun behind the viewer; and the duelling frusta, looking into the sun.
    auto flat = [](glm::dvec3 v) { return glm::normalize(glm::dvec3(v.x, 0.0, v.z)); };
    EXPECT_NEAR(glm::dot(flat(behind->forward()), sunFlat), 1.0, 1e-6);
    EXPECT_GT(glm::dot(behind->forward(), sun), 0.8);
    EXPECT_NEAR(glm::dot(flat(ahead->forward()), sunFlat), -1.0, 1e-6);
    EXPECT_LT(glm::dot(ahead->forward(), sun), -0.8);
    // The degenerate case: view direction equals the light direction.
    EXPECT_NEAR(glm::dot(alongSun->forward(), sun), 1.0, 1e-6);
    for (const InspectedNode* cam : {side, behind, ahead}) {
        EXPECT_NEAR(eyeHeight(cam), 1.8, 1e-3) << cam->name << " stands at eye height";
        for (const InspectedNode* t : f.childrenOf("Trees"))
            ASSERT_GT(glm::distance(glm::dvec2(t->position().x, t->position().z), glm::dvec2(cam->position().x, cam->position().z)), 3.5)
                << cam->name << " is inside " << t->name;
    }
    EXPECT_GT(eyeHeight(f.node("Camera_Aerial")), 30.0);
}

TEST(CubesScene, AxisAlignedCubesOnHillsUnderAnOverheadSun) {
    const Generated& g = defaultScene("cubes");
    ASSERT_TRUE(g.result.ok) << g.result.error;
    const Inspected& f = g.file_;
    const glm::dvec3 sun = lightDirection(f, "Sun_Overhead");
    EXPECT_NEAR(sun.y, -1.0, 1e-9) << "straight down: the cube sides are parallel to the light";
    const auto cubes = f.childrenOf("Cubes");
    ASSERT_EQ(cubes.size(), 3000u);
    const InspectedNode* hills = f.node("Hills");
    ASSERT_NE(hills, nullptr);
    struct Square {
        double x, z, half;
    };
    std::vector<Square> squares;
    for (std::size_t i = 0; i < cubes.size(); ++i) {
        const glm::dmat4& w = cubes[i]->world;
        // Axis-aligned: the world matrix is a pure scale plus translation.
        EXPECT_TRUE(w[0][1] == 0 && w[0][2] == 0 && w[1][0] == 0 && w[1][2] == 0 && w[2][0] == 0 && w[2][1] == 0) << cubes[i]->name;
        const double edge = w[0][0];
        EXPECT_GE(edge, 1.0 - 1e-4);
        EXPECT_LE(edge, 3.0 + 1e-4);
        squares.push_back({w[3][0], w[3][2], edge / 2});
        if (i % 61 == 0) {  // the bottom face is in the ground under all four corners
            const double bottom = w[3][1] - edge / 2;
            for (double dx : {-0.49, 0.49})
                for (double dz : {-0.49, 0.49}) {
                    const auto ground = groundHeight(f.model, hills->mesh, hills->world, w[3][0] + dx * edge, w[3][2] + dz * edge);
                    ASSERT_TRUE(ground.has_value());
                    EXPECT_LE(bottom, *ground + 1e-3) << cubes[i]->name << " floats";
                }
        }
    }
    // No two cubes overlap (sweep over x).
    std::sort(squares.begin(), squares.end(), [](const Square& a, const Square& b) { return a.x < b.x; });
    for (std::size_t i = 0; i < squares.size(); ++i)
        for (std::size_t j = i + 1; j < squares.size() && squares[j].x - squares[i].x < 3.0; ++j) {
            const bool overlap = std::abs(squares[i].x - squares[j].x) < squares[i].half + squares[j].half &&
                                 std::abs(squares[i].z - squares[j].z) < squares[i].half + squares[j].half;
            ASSERT_FALSE(overlap);
        }
}

TEST(ChessboardScene, ThirtyTwoPiecesOnTheBoardInsideTheSpotCone) {
    const Generated& g = defaultScene("chessboard");
    ASSERT_TRUE(g.result.ok) << g.result.error;
    const Inspected& f = g.file_;
    ASSERT_EQ(f.model.lights.size(), 1u);
    const tinygltf::Light& spot = f.model.lights[0];
    EXPECT_EQ(spot.type, "spot");
    EXPECT_LT(spot.spot.innerConeAngle, spot.spot.outerConeAngle);
    const InspectedNode* spotNode = f.node("Spot");
    ASSERT_NE(spotNode, nullptr);
    const auto pieces = f.childrenOf("Pieces");
    ASSERT_EQ(pieces.size(), 32u);
    std::set<std::string> squares;
    for (const InspectedNode* p : pieces) {
        squares.insert(p->name.substr(p->name.size() - 2));
        EXPECT_NEAR(p->position().y, 0.30, 1e-6) << p->name << " stands on the squares";
        EXPECT_LE(std::abs(p->position().x), 3.5 + 1e-9);
        EXPECT_LE(std::abs(p->position().z), 3.5 + 1e-9);
    }
    EXPECT_EQ(squares.size(), 32u) << "one piece per square";
    EXPECT_TRUE(f.node("King_White_e1") && f.node("Queen_Black_d8") && f.node("Pawn_White_a2"));
    // The whole board (corners at +-4 m) lies inside the spot's inner cone and range.
    for (double x : {-4.0, 4.0})
        for (double z : {-4.0, 4.0}) {
            const glm::dvec3 toCorner = glm::dvec3(x, 0.3, z) - spotNode->position();
            EXPECT_LT(std::acos(glm::dot(glm::normalize(toCorner), spotNode->forward())), spot.spot.innerConeAngle);
            EXPECT_LT(glm::length(toCorner), spot.range);
        }
}

TEST(StreetScene, DownTheStreetWithTheSunBehindAndAheadAndAHugeDepthRange) {
    const Generated& g = defaultScene("street");
    ASSERT_TRUE(g.result.ok) << g.result.error;
    const Inspected& f = g.file_;
    const glm::dvec3 sun = lightDirection(f, "Sun");
    const InspectedNode* behind = f.node("Camera_DownStreet_SunBehind");
    const InspectedNode* ahead = f.node("Camera_DownStreet_SunAhead");
    ASSERT_TRUE(behind && ahead);
    EXPECT_GT(glm::dot(behind->forward(), sun), 0.85) << "sun nearly behind the viewer";
    EXPECT_LT(glm::dot(ahead->forward(), sun), -0.85) << "sun nearly in front: duelling frusta";
    for (const tinygltf::Camera& c : f.model.cameras) EXPECT_GE(c.perspective.zfar / c.perspective.znear, 20000.0) << c.name;
    EXPECT_GE(f.hi.z - f.lo.z, 2000.0);
    // Buildings line both sides of the road and leave it free.
    std::size_t west = 0, east = 0;
    for (const InspectedNode* b : f.childrenOf("Buildings")) {
        const double halfDepth = b->world[0][0] / 2;
        EXPECT_GE(std::abs(b->position().x) - halfDepth, 11.0 - 1e-3) << b->name;
        (b->position().x < 0 ? west : east)++;
    }
    EXPECT_GT(west, 50u);
    EXPECT_GT(east, 50u);
    // Looking down the street, the eye sees the far end: nothing stands on the road in front of it.
    for (const InspectedNode* car : f.childrenOf("Cars")) EXPECT_GT(std::abs(car->position().x), 3.0);
}

TEST(PlaneBoxScene, ExactlyTheDocumentedSanityScene) {
    const Generated& g = defaultScene("plane-box");
    ASSERT_TRUE(g.result.ok) << g.result.error;
    const Inspected& f = g.file_;
    const tinygltf::Model& m = f.model;
    ASSERT_EQ(m.nodes.size(), 4u);
    EXPECT_EQ(m.nodes[0].name, "Ground");
    EXPECT_EQ(m.nodes[1].name, "Box");
    EXPECT_EQ(m.nodes[2].name, "Sun");
    EXPECT_EQ(m.nodes[3].name, "Camera_Main");
    // Ground: two triangles, 20 x 20 m at y = 0 centred at the origin, facing up.
    const auto ground = readVec3(m, m.meshes[std::size_t(m.nodes[0].mesh)].primitives[0].attributes.at("POSITION"));
    EXPECT_EQ(meshTriangles(m, m.nodes[0].mesh), 2u);
    for (const glm::vec3& v : ground) {
        EXPECT_EQ(std::abs(v.x), 10.0f);
        EXPECT_EQ(v.y, 0.0f);
        EXPECT_EQ(std::abs(v.z), 10.0f);
    }
    // Box: 2 m cube centred at (0, 1, 0).
    EXPECT_EQ(meshTriangles(m, m.nodes[1].mesh), 12u);
    EXPECT_EQ(f.node("Box")->position(), glm::dvec3(0, 1, 0));
    EXPECT_EQ(f.lo, glm::dvec3(-10, 0, -10));
    EXPECT_EQ(f.hi, glm::dvec3(10, 2, 10));
    // Materials.
    ASSERT_EQ(m.materials.size(), 2u);
    EXPECT_EQ(m.materials[std::size_t(m.meshes[std::size_t(m.nodes[0].mesh)].primitives[0].material)].name, "Ground");
    EXPECT_EQ(m.materials[0].pbrMetallicRoughness.baseColorFactor, (std::vector<double>{0.8, 0.8, 0.8, 1.0}));
    EXPECT_EQ(m.materials[1].name, "Box");
    EXPECT_EQ(m.materials[1].pbrMetallicRoughness.baseColorFactor, (std::vector<double>{0.8, 0.1, 0.1, 1.0}));
    // Sun down and slightly sideways.
    EXPECT_EQ(m.lights[0].name, "Sun");
    EXPECT_EQ(m.lights[0].type, "directional");
    const glm::dvec3 sun = lightDirection(f, "Sun");
    const glm::dvec3 expected = glm::normalize(glm::dvec3(-0.3, -1.0, -0.2));
    EXPECT_NEAR(glm::distance(sun, expected), 0.0, 1e-6);
    // The camera at (0, 6, 12) looks at the box centre.
    const InspectedNode* cam = f.node("Camera_Main");
    EXPECT_NEAR(glm::distance(cam->position(), glm::dvec3(0, 6, 12)), 0.0, 1e-9);
    EXPECT_NEAR(glm::distance(cam->forward(), glm::normalize(glm::dvec3(0, 1, 0) - glm::dvec3(0, 6, 12))), 0.0, 1e-6);
    const glm::dvec3 camUp(cam->world * glm::dvec4(0, 1, 0, 0));
    EXPECT_GT(camUp.y, 0.9) << "upright";
    EXPECT_DOUBLE_EQ(m.cameras[0].perspective.zfar, 100.0);
}

}  // namespace
}  // namespace shadowlab::test
