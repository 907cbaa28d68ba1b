// cubes: thesis Fig. 3.5 - thousands of axis-aligned green cubes on green hills, lit from
// straight above. Their vertical sides are parallel to the light: the extreme case of
// projection aliasing (a whole side falls into a single shadow map texel row).
#include "generators_internal.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace shadowlab::scenegen {

void buildCubes(GltfBuilder& builder, const GenerateOptions& options) {
    const double s = options.scale;
    const std::size_t cubeCount = std::max<std::size_t>(1, std::size_t(std::llround(3000.0 * s)));
    const double side = 240.0 * std::sqrt(s);  // 3,000 cubes per 240 m x 240 m
    const int cells = std::max(8, int(std::lround(128.0 * std::sqrt(s))));
    const double half = side / 2.0;

    Random terrainRandom(options.seed, 1), placeRandom(options.seed, 2);
    const RollingHills hills(terrainRandom, {{120.0, 4.0}, {75.0, 2.5}, {45.0, 1.2}, {25.0, 0.5}});
    const HeightGrid grid = HeightGrid::sample(-half, -half, half, half, cells, cells, hills);

    const int hillsMaterial = builder.addMaterial("Hills_Green", {0.18f, 0.42f, 0.12f, 1.0f});
    const int cubeMaterials[3] = {builder.addMaterial("Cube_GreenLight", {0.35f, 0.62f, 0.25f, 1.0f}),
                                  builder.addMaterial("Cube_GreenDark", {0.10f, 0.32f, 0.08f, 1.0f}),
                                  builder.addMaterial("Cube_GreenYellow", {0.45f, 0.55f, 0.12f, 1.0f})};
    const MeshData terrain = grid.mesh();
    const int terrainMesh = builder.addMesh("Hills", {{&terrain, hillsMaterial}});
    const MeshData unitCube = box({-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f});
    const int cubeMeshes[3] = {builder.addMesh("Cube_GreenLight", {{&unitCube, cubeMaterials[0]}}),
                               builder.addMesh("Cube_GreenDark", {{&unitCube, cubeMaterials[1]}}),
                               builder.addMesh("Cube_GreenYellow", {{&unitCube, cubeMaterials[2]}})};
    const char* colourNames[3] = {"GreenLight", "GreenDark", "GreenYellow"};

    const double reach = std::min(1.0, 0.3 * half / 40.0);
    const glm::dvec3 mainEye(-40.0 * reach, grid.surfaceHeight(-40.0 * reach, 40.0 * reach) + 12.0, 40.0 * reach);
    const glm::dvec3 groundEye(0.0, grid.surfaceHeight(0.0, 0.0) + 1.8, 0.0);

    builder.setMesh(builder.addNode("Hills", {}), terrainMesh);
    const int cubesGroup = builder.addNode("Cubes", {});
    const double margin = 3.0;
    const std::size_t maxAttempts = cubeCount * 200 + 1000;
    PlacementGrid occupied(4.0);  // two cubes of at most 3 m plus the 0.5 m gap fit in 3.5 m
    std::size_t placed = 0;
    for (std::size_t attempt = 0; placed < cubeCount; ++attempt) {
        if (attempt >= maxAttempts) throw std::runtime_error("could not place the cubes (too dense)");
        const glm::dvec2 p(placeRandom.uniform(-half + margin, half - margin), placeRandom.uniform(-half + margin, half - margin));
        const double edge = placeRandom.uniform(1.0, 3.0);
        const std::uint32_t colour = placeRandom.below(3);
        // No overlaps (axis-aligned squares) and a clearing around the eye-level camera.
        bool clear = glm::distance(p, glm::dvec2(groundEye.x, groundEye.z)) > 4.0 + edge;
        clear = clear && occupied.allNear(p, [&](glm::dvec2 q, double qEdge) {
            const double minGap = (edge + qEdge) / 2.0 + 0.5;
            return std::abs(p.x - q.x) >= minGap || std::abs(p.y - q.y) >= minGap;
        });
        if (!clear) continue;
        occupied.add(p, edge);
        // Standing on its lowest footprint corner, so no side floats above the hill.
        double base = grid.surfaceHeight(p.x, p.y);
        for (double dx : {-0.5, 0.5})
            for (double dz : {-0.5, 0.5}) base = std::min(base, grid.surfaceHeight(p.x + dx * edge, p.y + dz * edge));
        Transform t;
        t.translation = glm::dvec3(p.x, base - 0.05 + edge / 2.0, p.y);
        t.scale = glm::dvec3(edge);
        const int node = builder.addNode("Cube_" + padded(placed, 4) + "_" + colourNames[colour], t, cubesGroup);
        builder.setMesh(node, cubeMeshes[colour]);
        ++placed;
    }

    // Straight down: the cube sides are exactly parallel to the light.
    const glm::dvec3 down(0.0, -1.0, 0.0);
    const int sun = builder.addDirectionalLight("Sun_Overhead", {1.0, 0.97, 0.9}, 3.0);
    builder.addLightNode("Sun_Overhead", sun, glm::dvec3(0.0, 100.0, 0.0), down);
    const int mainCamera = builder.addPerspectiveCamera("Camera_Main", 60.0 * kDegree, 0.1, 100.0);
    builder.addCameraNode("Camera_Main", mainCamera, mainEye, glm::normalize(glm::dvec3(1.0, -0.35, -1.0)));
    const int groundCamera = builder.addPerspectiveCamera("Camera_AlongGround", 60.0 * kDegree, 0.1, 100.0);
    builder.addCameraNode("Camera_AlongGround", groundCamera, groundEye, glm::normalize(glm::dvec3(1.0, -0.05, 0.0)));
}

}  // namespace shadowlab::scenegen
