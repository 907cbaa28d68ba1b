// Worlds that tile and worlds in one piece: the forest's terrain as tiles of their own nodes (the
// same surface as one grid), and `--merge`, which bakes every instance into one huge mesh with the
// same triangles, materials, cameras and lights.
#include "generated_scenes.h"
#include "scenes/generators/geometry.h"

#include <gtest/gtest.h>

#include <map>

namespace shadowlab::test {
namespace {

using scenegen::GenerateOptions;

TEST(TerrainTiles, TilesOfAGridAreTheGridsVerticesNormalsAndTriangles) {
    const auto height = [](double x, double z) { return std::sin(0.3 * x) * 2.0 + std::cos(0.2 * z); };
    const scenegen::HeightGrid grid = scenegen::HeightGrid::sample(-20.0, -10.0, 20.0, 14.0, 20, 12, height);
    const scenegen::MeshData whole = grid.mesh();
    // Tiles of 8 x 5 cells (the last ones smaller): every tile vertex is the whole mesh's vertex at
    // that grid point, bit for bit, normal included.
    std::size_t triangles = 0;
    for (int k0 = 0; k0 < grid.cellsZ; k0 += 5)
        for (int i0 = 0; i0 < grid.cellsX; i0 += 8) {
            const int i1 = std::min(i0 + 8, grid.cellsX), k1 = std::min(k0 + 5, grid.cellsZ);
            const scenegen::MeshData tile = grid.mesh(i0, k0, i1, k1);
            ASSERT_EQ(tile.positions.size(), std::size_t((i1 - i0 + 1) * (k1 - k0 + 1)));
            for (int k = k0; k <= k1; ++k)
                for (int i = i0; i <= i1; ++i) {
                    const std::size_t t = std::size_t((k - k0) * (i1 - i0 + 1) + (i - i0));
                    const std::size_t w = std::size_t(k * (grid.cellsX + 1) + i);
                    ASSERT_EQ(tile.positions[t], whole.positions[w]);
                    ASSERT_EQ(tile.normals[t], whole.normals[w]);
                }
            triangles += tile.triangleCount();
        }
    EXPECT_EQ(triangles, whole.triangleCount());
}

TEST(TerrainTiles, ForestTilesMeetWithoutSeams) {
    GenerateOptions options;
    options.scale = 0.1;  // 81 x 81 cells: tiles of 32, 32 and 17 cells per side
    const GeneratedScene& g = generatedScene("forest", options);
    ASSERT_TRUE(g.result.ok) << g.result.error;
    const auto tiles = g.inspected.childrenOf("Terrain");
    ASSERT_EQ(tiles.size(), 9u);
    // Where tiles share a border vertex, they agree on its height and normal.
    std::map<std::pair<float, float>, std::pair<glm::vec3, glm::vec3>> seen;
    std::size_t shared = 0, triangles = 0;
    for (const InspectedNode* tile : tiles) {
        EXPECT_EQ(tile->world, glm::dmat4(1.0)) << tile->name;
        const tinygltf::Primitive& p = g.inspected.model.meshes[std::size_t(tile->mesh)].primitives[0];
        const auto positions = readVec3(g.inspected.model, p.attributes.at("POSITION"));
        const auto normals = readVec3(g.inspected.model, p.attributes.at("NORMAL"));
        triangles += meshTriangles(g.inspected.model, tile->mesh);
        for (std::size_t i = 0; i < positions.size(); ++i) {
            const auto [it, added] =
                seen.emplace(std::make_pair(positions[i].x, positions[i].z), std::make_pair(positions[i], normals[i]));
            if (added) continue;
            ++shared;
            ASSERT_EQ(it->second.first, positions[i]);
            ASSERT_EQ(it->second.second, normals[i]);
        }
    }
    // Four seam lines of 82 grid points; the 4 points where they cross are in four tiles each.
    EXPECT_EQ(shared, 4u * 82u + 4u);
    EXPECT_EQ(triangles, 2u * 81u * 81u);
}

// Per material: triangle count, total area and area-weighted normal sum in world space.
struct MaterialSums {
    std::size_t triangles = 0;
    double area = 0.0;
    glm::dvec3 normal{0.0};
};
std::map<std::string, MaterialSums> materialSums(const Inspected& f) {
    std::map<std::string, MaterialSums> sums;
    for (const InspectedNode& n : f.nodes) {
        if (n.mesh < 0) continue;
        for (const tinygltf::Primitive& p : f.model.meshes[std::size_t(n.mesh)].primitives) {
            MaterialSums& s = sums[f.model.materials[std::size_t(p.material)].name];
            const auto pos = readVec3(f.model, p.attributes.at("POSITION"));
            const auto nrm = readVec3(f.model, p.attributes.at("NORMAL"));
            const auto idx = readIndices(f.model, p.indices);
            const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(n.world)));
            for (std::size_t t = 0; t + 2 < idx.size(); t += 3) {
                glm::dvec3 w[3], vertexNormals(0.0);
                for (std::size_t k = 0; k < 3; ++k) {
                    w[k] = glm::dvec3(n.world * glm::dvec4(glm::dvec3(pos[idx[t + k]]), 1.0));
                    vertexNormals += normalMatrix * glm::dvec3(nrm[idx[t + k]]);
                }
                const glm::dvec3 face = glm::cross(w[1] - w[0], w[2] - w[0]);
                ++s.triangles;
                s.area += 0.5 * glm::length(face);
                s.normal += 0.5 * face;
                // Winding and vertex normals still agree after baking (mirrors turn the winding).
                EXPECT_GT(glm::dot(face, vertexNormals), -1e-9) << n.name;
            }
        }
    }
    return sums;
}

struct MergeCase {
    std::string name;
    double scale;
};

class MergedScene : public ::testing::TestWithParam<MergeCase> {};

TEST_P(MergedScene, IsOneMeshWithTheSameTrianglesMaterialsCamerasAndLights) {
    GenerateOptions options;
    options.scale = GetParam().scale;
    const GeneratedScene& plain = generatedScene(GetParam().name, options);
    options.merge = true;
    const GeneratedScene& merged = generatedScene(GetParam().name, options);
    ASSERT_TRUE(plain.result.ok && merged.result.ok) << plain.result.error << merged.result.error;
    const Inspected &a = plain.inspected, &b = merged.inspected;
    ASSERT_TRUE(b.error.empty()) << b.error;
    EXPECT_EQ(b.meshInstances, 1u);
    EXPECT_EQ(b.model.meshes.size(), 1u);
    const InspectedNode* node = b.node("World_Merged");
    ASSERT_NE(node, nullptr);
    EXPECT_EQ(node->world, glm::dmat4(1.0));
    EXPECT_EQ(b.triangles, a.triangles);
    EXPECT_EQ(merged.result.stats.triangles, plain.result.stats.triangles);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(b.lo[i], a.lo[i], 1e-3);
        EXPECT_NEAR(b.hi[i], a.hi[i], 1e-3);
    }
    // The same surface per material: triangles, area and orientation.
    const auto before = materialSums(a), after = materialSums(b);
    ASSERT_EQ(before.size(), after.size());
    for (const auto& [material, s] : before) {
        ASSERT_TRUE(after.count(material)) << material;
        const MaterialSums& m = after.at(material);
        EXPECT_EQ(m.triangles, s.triangles) << material;
        EXPECT_NEAR(m.area, s.area, 1e-5 * s.area) << material;
        EXPECT_NEAR(glm::distance(m.normal, s.normal), 0.0, 1e-5 * s.area) << material;
    }
    EXPECT_TRUE(a.model.materials == b.model.materials);
    EXPECT_TRUE(a.model.cameras == b.model.cameras);
    EXPECT_TRUE(a.model.lights == b.model.lights);
    // Cameras and lights where they were, in the same order ("--camera 0" is the same view).
    std::vector<std::string> placedBefore, placedAfter;
    for (const InspectedNode& n : a.nodes)
        if (n.camera >= 0 || n.light >= 0) placedBefore.push_back(n.name);
    for (const InspectedNode& n : b.nodes)
        if (n.camera >= 0 || n.light >= 0) placedAfter.push_back(n.name);
    EXPECT_EQ(placedAfter, placedBefore);
    for (const InspectedNode& n : a.nodes) {
        if (n.camera < 0 && n.light < 0) continue;
        const InspectedNode* m = b.node(n.name);
        ASSERT_NE(m, nullptr) << n.name;
        EXPECT_EQ(m->camera, n.camera);
        EXPECT_EQ(m->light, n.light);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) EXPECT_NEAR(m->world[c][r], n.world[c][r], 1e-6) << n.name;
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, MergedScene,
                         ::testing::Values(MergeCase{"forest", 0.05}, MergeCase{"street", 0.1},
                                           MergeCase{"chessboard", 1.0}, MergeCase{"interior", 1.0}),
                         [](const auto& info) { return info.param.name; });

TEST(MergedScene, IsDeterministicAndKeepsTheSkyBoxApart) {
    GenerateOptions options;
    options.scale = 0.1;
    options.merge = true;
    options.skyBox = true;
    const GeneratedScene& g = generatedScene("street", options);
    ASSERT_TRUE(g.result.ok) << g.result.error;
    EXPECT_EQ(g.inspected.meshInstances, 2u);
    EXPECT_NE(g.inspected.node("World_Merged"), nullptr);
    EXPECT_NE(g.inspected.node("SkyBox"), nullptr);
    const std::filesystem::path again = tempDir() / "street-merged-again.glb";
    ASSERT_TRUE(scenegen::generateScene("street", options, again).ok);
    EXPECT_TRUE(readBytes(g.file) == readBytes(again));
}

}  // namespace
}  // namespace shadowlab::test
