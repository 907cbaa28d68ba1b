// forest: the thesis test scene (ch. 9 and 10, Fig. 10.1): an outdoor environment of tree-like
// objects on rolling terrain, one directional sun, cameras with fov 60 deg, near 0.1, far 70.
// The thesis used 5,000 trees; this scene has 10,000 (x scale) for a polygon-rich load.
#include "generators_internal.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace shadowlab::scenegen {

namespace {

struct TreeVariant {
    const char* name;
    int permille;  // share of the trees
    int mesh = -1;
};

}  // namespace

void buildForest(GltfBuilder& builder, const GenerateOptions& options) {
    const double s = options.scale;
    const std::size_t treeCount = std::max<std::size_t>(1, std::size_t(std::llround(10000.0 * s)));
    const double side = 512.0 * std::sqrt(s);  // constant density: 10,000 trees per 512 m x 512 m
    const int cells = std::max(8, int(std::lround(256.0 * std::sqrt(s))));  // 2 m cells
    const double half = side / 2.0;

    Random terrainRandom(options.seed, 1), placeRandom(options.seed, 2);
    const RollingHills hills(terrainRandom, {{260.0, 6.0}, {170.0, 4.0}, {110.0, 2.5}, {70.0, 1.5}, {40.0, 0.7}, {23.0, 0.3}});
    const HeightGrid grid = HeightGrid::sample(-half, -half, half, half, cells, cells, hills);

    // Materials (linear colours).
    const int grass = builder.addMaterial("Terrain_Grass", {0.26f, 0.40f, 0.14f, 1.0f});
    const int bark = builder.addMaterial("Bark_Brown", {0.28f, 0.18f, 0.10f, 1.0f});
    const int birchBark = builder.addMaterial("Bark_Birch", {0.80f, 0.78f, 0.72f, 1.0f});
    const int spruceLeaves = builder.addMaterial("Leaves_Spruce", {0.06f, 0.22f, 0.09f, 1.0f});
    const int pineLeaves = builder.addMaterial("Leaves_Pine", {0.14f, 0.33f, 0.11f, 1.0f});
    const int oakLeaves = builder.addMaterial("Leaves_Oak", {0.20f, 0.45f, 0.12f, 1.0f});
    const int birchLeaves = builder.addMaterial("Leaves_Birch", {0.42f, 0.60f, 0.20f, 1.0f});
    const int firLeaves = builder.addMaterial("Leaves_Fir", {0.04f, 0.18f, 0.14f, 1.0f});
    const int autumnLeaves = builder.addMaterial("Leaves_Autumn", {0.75f, 0.33f, 0.07f, 1.0f});

    // The terrain as square tiles of the grid, each its own mesh and node under "Terrain": the same
    // surface, normals and triangle count as one grid mesh, but a view or a light that reaches only
    // part of the world can skip whole tiles.
    constexpr int kTileCells = 32;  // 64 m tiles of 2,048 triangles
    std::vector<std::pair<std::string, int>> terrainTiles;
    for (int k0 = 0; k0 < cells; k0 += kTileCells)
        for (int i0 = 0; i0 < cells; i0 += kTileCells) {
            const MeshData tile =
                grid.mesh(i0, k0, std::min(i0 + kTileCells, cells), std::min(k0 + kTileCells, cells));
            const std::string name = "Terrain_" + padded(std::size_t(k0 / kTileCells), 2) + "_" +
                                     padded(std::size_t(i0 / kTileCells), 2);
            terrainTiles.emplace_back(name, builder.addMesh(name, {{&tile, grass}}));
        }

    // Tree variants, origin at the foot of the trunk; trunks reach 0.5 m below it so they stay
    // in the ground on slopes. Triangles per variant are listed in scenes/README.md.
    std::vector<TreeVariant> variants = {{"Spruce", 300}, {"Pine", 150}, {"Oak", 200},
                                         {"Birch", 150},  {"Fir", 100},  {"Autumn", 100}};
    {
        MeshData trunk = cylinderSide(0.25f, -0.5f, 3.0f, 8), crown;
        crown.append(cone(2.2f, 1.2f, 4.4f, 16));
        crown.append(cone(1.7f, 3.0f, 6.2f, 16));
        crown.append(cone(1.2f, 4.8f, 8.0f, 16));
        variants[0].mesh = builder.addMesh("Tree_Spruce", {{&trunk, bark}, {&crown, spruceLeaves}});
    }
    {
        MeshData trunk = cylinderSide(0.3f, -0.5f, 7.5f, 8);
        MeshData crown = ellipsoid({0.0f, 8.3f, 0.0f}, {2.4f, 1.6f, 2.4f}, 12, 8);
        variants[1].mesh = builder.addMesh("Tree_Pine", {{&trunk, bark}, {&crown, pineLeaves}});
    }
    {
        MeshData trunk = cylinderSide(0.4f, -0.5f, 4.0f, 10);
        MeshData crown = ellipsoid({0.0f, 5.8f, 0.0f}, {3.2f, 2.8f, 3.2f}, 16, 10);
        variants[2].mesh = builder.addMesh("Tree_Oak", {{&trunk, bark}, {&crown, oakLeaves}});
    }
    {
        MeshData trunk = cylinderSide(0.18f, -0.5f, 5.0f, 8);
        MeshData crown = ellipsoid({0.0f, 6.5f, 0.0f}, {1.7f, 3.0f, 1.7f}, 14, 9);
        variants[3].mesh = builder.addMesh("Tree_Birch", {{&trunk, birchBark}, {&crown, birchLeaves}});
    }
    {
        MeshData trunk = cylinderSide(0.2f, -0.5f, 2.0f, 8), crown;
        crown.append(cone(1.6f, 1.0f, 3.6f, 12));
        crown.append(cone(1.3f, 2.6f, 5.0f, 12));
        crown.append(cone(1.0f, 4.0f, 6.3f, 12));
        crown.append(cone(0.7f, 5.4f, 7.6f, 12));
        variants[4].mesh = builder.addMesh("Tree_Fir", {{&trunk, bark}, {&crown, firLeaves}});
    }
    {
        MeshData trunk = cylinderSide(0.3f, -0.5f, 3.5f, 8);
        MeshData crown = ellipsoid({0.0f, 4.8f, 0.0f}, {2.6f, 2.3f, 2.6f}, 14, 8);
        variants[5].mesh = builder.addMesh("Tree_Autumn", {{&trunk, bark}, {&crown, autumnLeaves}});
    }

    // The sun: 30 deg above the horizon, its light travelling towards +X and a little +Z.
    const glm::dvec3 sunDirection = sunTravelDirection(30.0 * kDegree, 20.0 * kDegree);
    const glm::dvec3 sunHorizontal = glm::normalize(glm::dvec3(sunDirection.x, 0.0, sunDirection.z));
    const glm::dvec3 sideways = glm::cross(sunHorizontal, glm::dvec3(0.0, 1.0, 0.0));  // horizontal, perpendicular

    // Camera presets (thesis ch. 10: fov 60 deg, near 0.1, far 70). Eye-level cameras stand
    // 1.8 m above the terrain in small clearings (no tree within 3.5 m).
    const double reach = std::min(1.0, 0.3 * half / 60.0);  // keeps the eyes inside small scaled terrains
    auto eyeAt = [&](double x, double z, double height) {
        return glm::dvec3(x * reach, grid.surfaceHeight(x * reach, z * reach) + height, z * reach);
    };
    const auto pitched = pitchedDirection;
    const std::vector<CameraPreset> presets = {
        // LiSPSM's best case: view perpendicular to the light, looking along the ground (thesis 8.2.4).
        {"Camera_AlongGround_SunSide", eyeAt(0.0, 0.0, 1.8), pitched(sideways, -3.0)},
        // PSM's hard case: the sun behind the viewer (light source behind the eye, thesis 7.2.2).
        {"Camera_AlongGround_SunBehind", eyeAt(-30.0, 20.0, 1.8), pitched(sunHorizontal, -5.0)},
        // Duelling frusta: looking into the sun (thesis 8.2.5).
        {"Camera_AlongGround_SunAhead", eyeAt(25.0, -35.0, 1.8), pitched(-sunHorizontal, -3.0)},
        // Above the trees, looking down at 35 deg across the hills.
        {"Camera_Aerial", eyeAt(60.0, 40.0, 40.0), pitched(glm::normalize(glm::dvec3(-1.0, 0.0, -0.6)), -35.0)},
        // View direction equal to the light direction: the degenerate case (sin gamma = 0).
        {"Camera_AlongSun", eyeAt(-50.0, -45.0, 30.0), sunDirection},
    };

    // Terrain and trees.
    const int terrainGroup = builder.addNode("Terrain", {});
    for (const auto& [name, mesh] : terrainTiles) builder.setMesh(builder.addNode(name, {}, terrainGroup), mesh);
    const int treesGroup = builder.addNode("Trees", {});
    PlacementGrid spacing(2.0);  // trunks at least 2 m apart
    const double margin = 3.0;
    const std::size_t maxAttempts = treeCount * 200 + 1000;
    std::size_t placed = 0;
    for (std::size_t attempt = 0; placed < treeCount; ++attempt) {
        if (attempt >= maxAttempts) throw std::runtime_error("could not place the trees (too dense)");
        const glm::dvec2 p(placeRandom.uniform(-half + margin, half - margin), placeRandom.uniform(-half + margin, half - margin));
        const double yaw = placeRandom.uniform(0.0, 2.0 * std::numbers::pi);
        const double size = placeRandom.uniform(0.8, 1.25);
        const std::uint32_t pick = placeRandom.below(1000);
        bool clear = spacing.allNear(p, [&](glm::dvec2 q, double) { return glm::distance(p, q) >= 2.0; });
        for (const CameraPreset& preset : presets)
            if (preset.eye.y - grid.surfaceHeight(preset.eye.x, preset.eye.z) < 5.0 &&
                glm::distance(p, glm::dvec2(preset.eye.x, preset.eye.z)) < 3.5)
                clear = false;
        if (!clear) continue;
        spacing.add(p, 0.0);
        std::size_t v = 0;
        for (int acc = 0; v + 1 < variants.size(); ++v) {
            acc += variants[v].permille;
            if (int(pick) < acc) break;
        }
        Transform t;
        t.translation = glm::dvec3(p.x, grid.surfaceHeight(p.x, p.y) - 0.1, p.y);  // a little into the ground
        t.rotation = glm::angleAxis(yaw, glm::dvec3(0.0, 1.0, 0.0));
        t.scale = glm::dvec3(size);
        const int node = builder.addNode("Tree_" + padded(placed, 5) + "_" + variants[v].name, t, treesGroup);
        builder.setMesh(node, variants[v].mesh);
        ++placed;
    }

    const int sun = builder.addDirectionalLight("Sun", {1.0, 0.96, 0.88}, 3.0);
    builder.addLightNode("Sun", sun, glm::dvec3(0.0, 100.0, 0.0) - 100.0 * sunDirection, sunDirection);
    addCameraPresets(builder, presets, 0.1, 70.0);
}

}  // namespace shadowlab::scenegen
