// street: a long straight street between buildings, eye-level cameras looking down it with the
// sun nearly behind the viewer or nearly in front (the duelling frusta, thesis 8.2.5 and the
// robust-shadow-maps paper Fig. 11), and a very large depth range (near 0.1, far > 2 km).
// Echoes the PSM paper's street scene (Fig. 9): cars and lamp posts give small near casters.
#include "generators_internal.h"

#include <algorithm>
#include <cmath>

namespace shadowlab::scenegen {

void buildStreet(GltfBuilder& builder, const GenerateOptions& options) {
    const double length = 2000.0 * options.scale;  // along Z, from +length/2 (start) to -length/2
    const double halfLength = length / 2.0;
    Random buildingRandom(options.seed, 1), carRandom(options.seed, 2);

    const int groundMaterial = builder.addMaterial("Ground_Grass", {0.22f, 0.35f, 0.14f, 1.0f});
    const int roadMaterial = builder.addMaterial("Road_Asphalt", {0.08f, 0.08f, 0.09f, 1.0f});
    const int sidewalkMaterial = builder.addMaterial("Sidewalk_Concrete", {0.55f, 0.54f, 0.50f, 1.0f});
    const int metalMaterial = builder.addMaterial("LampPost_Metal", {0.15f, 0.16f, 0.17f, 1.0f}, 0.5f);
    const int lampMaterial = builder.addMaterial("Lamp_Glass", {0.95f, 0.92f, 0.75f, 1.0f}, 0.3f);
    const char* facadeNames[5] = {"Brick", "Sandstone", "Plaster", "Concrete", "Glass"};
    const glm::vec4 facadeColours[5] = {{0.45f, 0.18f, 0.12f, 1.0f},
                                        {0.70f, 0.58f, 0.40f, 1.0f},
                                        {0.85f, 0.83f, 0.78f, 1.0f},
                                        {0.45f, 0.45f, 0.45f, 1.0f},
                                        {0.25f, 0.35f, 0.45f, 1.0f}};
    const char* carNames[4] = {"Red", "Blue", "White", "Black"};
    const glm::vec4 carColours[4] = {{0.6f, 0.05f, 0.04f, 1.0f},
                                     {0.05f, 0.15f, 0.5f, 1.0f},
                                     {0.85f, 0.85f, 0.85f, 1.0f},
                                     {0.03f, 0.03f, 0.03f, 1.0f}};

    // Ground: grass wider than the street block, the asphalt road 12 m wide (2 cm above the
    // grass) and two 4 m sidewalks 15 cm high (kerbs throw thin shadows along the street). Each
    // is cut into equal tiles of at most 500 m along the street, each its own mesh and node, so a
    // light's frustum or a view that does not reach a whole long street can skip stretches. Long
    // tiles: the cameras see the whole street (far = its length), so every tile is one more draw.
    constexpr double kTileLength = 500.0;
    const float gx = 120.0f, gz = float(halfLength + 60.0), rz = float(halfLength + 20.0);
    auto addTiles = [&](const std::string& name, float half, int material, auto makeTile) {
        const int tiles = std::max(1, int(std::ceil(2.0 * half / kTileLength)));
        std::vector<int> meshes;
        for (int i = 0; i < tiles; ++i) {
            const float z0 = -half + 2.0f * half * float(i) / float(tiles);
            const float z1 = i + 1 == tiles ? half : -half + 2.0f * half * float(i + 1) / float(tiles);
            const MeshData tile = makeTile(z0, z1);
            meshes.push_back(builder.addMesh(name + "_" + padded(std::size_t(i), 3), {{&tile, material}}));
        }
        return meshes;
    };
    auto flat = [](float x0, float x1, float y) {
        return [=](float z0, float z1) {
            MeshData m;
            m.addQuad({x0, y, z0}, {x0, y, z1}, {x1, y, z1}, {x1, y, z0}, {0, 1, 0});
            return m;
        };
    };
    const std::vector<int> groundMeshes = addTiles("Ground", gz, groundMaterial, flat(-gx, gx, 0.0f));
    const std::vector<int> roadMeshes = addTiles("Road", rz, roadMaterial, flat(-6.0f, 6.0f, 0.02f));
    const std::vector<int> sidewalkMeshes = addTiles("Sidewalks", rz, sidewalkMaterial, [](float z0, float z1) {
        MeshData m = box({-10.0f, 0.0f, z0}, {-6.0f, 0.15f, z1});
        m.append(box({6.0f, 0.0f, z0}, {10.0f, 0.15f, z1}));
        return m;
    });

    // Buildings: unit boxes standing on y = 0, scaled per building.
    const MeshData unitBuilding = box({-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f});
    int buildingMeshes[5];
    for (int i = 0; i < 5; ++i)
        buildingMeshes[i] = builder.addMesh(std::string("Building_") + facadeNames[i],
                                            {{&unitBuilding, builder.addMaterial(std::string("Facade_") + facadeNames[i], facadeColours[i])}});

    // Lamp post: pole, arm over the road, lamp head. Origin at the foot, arm towards +X.
    MeshData pole = cylinderSide(0.08f, 0.0f, 6.0f, 8);
    MeshData arm = box({0.0f, 5.9f, -0.05f}, {1.5f, 6.0f, 0.05f});
    pole.append(arm);
    MeshData head = box({1.2f, 5.75f, -0.15f}, {1.6f, 5.9f, 0.15f});
    const int lampMesh = builder.addMesh("LampPost", {{&pole, metalMaterial}, {&head, lampMaterial}});

    // Car: body and cabin, 4.2 m long along Z.
    MeshData carBody = box({-0.9f, 0.3f, -2.1f}, {0.9f, 1.0f, 2.1f});
    carBody.append(box({-0.8f, 1.0f, -1.0f}, {0.8f, 1.5f, 1.0f}));
    int carMeshes[4];
    for (int i = 0; i < 4; ++i)
        carMeshes[i] = builder.addMesh(std::string("Car_") + carNames[i],
                                       {{&carBody, builder.addMaterial(std::string("Car_") + carNames[i], carColours[i], 0.4f)}});

    const std::pair<const char*, const std::vector<int>*> tileGroups[] = {
        {"Ground", &groundMeshes}, {"Road", &roadMeshes}, {"Sidewalks", &sidewalkMeshes}};
    for (const auto& [group, meshes] : tileGroups) {
        const int parent = builder.addNode(group, {});
        for (const int mesh : *meshes)
            builder.setMesh(builder.addNode(builder.model().meshes[std::size_t(mesh)].name, {}, parent), mesh);
    }

    const int buildingsGroup = builder.addNode("Buildings", {});
    std::size_t buildingIndex = 0;
    for (int sideSign : {-1, 1}) {
        const char* sideName = sideSign < 0 ? "West" : "East";
        double z = -halfLength;
        while (true) {
            const double width = buildingRandom.uniform(8.0, 30.0);  // along the street
            const double depth = buildingRandom.uniform(10.0, 25.0);
            // Mostly 2 to 8 storeys, one in eight a tower up to 80 m.
            const bool tower = buildingRandom.below(8) == 0;
            const double height = tower ? buildingRandom.uniform(40.0, 80.0) : buildingRandom.uniform(6.0, 25.0);
            const double setback = buildingRandom.uniform(0.0, 3.0);
            const std::uint32_t facade = buildingRandom.below(5);
            const double gap = buildingRandom.uniform(0.0, 6.0);
            if (z + width > halfLength) break;
            Transform t;
            t.translation = glm::dvec3(sideSign * (11.0 + setback + depth / 2.0), 0.0, z + width / 2.0);
            t.scale = glm::dvec3(depth, height, width);
            builder.setMesh(builder.addNode("Building_" + padded(buildingIndex++, 4) + "_" + sideName + "_" + facadeNames[facade], t,
                                            buildingsGroup),
                            buildingMeshes[facade]);
            z += width + gap;
        }
    }

    const int lampsGroup = builder.addNode("LampPosts", {});
    std::size_t lampIndex = 0;
    for (double z = -halfLength + 10.0; z <= halfLength - 10.0; z += 25.0)
        for (int sideSign : {-1, 1}) {
            Transform t;
            t.translation = glm::dvec3(sideSign * 8.5, 0.15, z);
            // The arm points over the road: +X for the west row, turned 180 deg for the east row.
            if (sideSign > 0) t.rotation = glm::angleAxis(std::numbers::pi, glm::dvec3(0.0, 1.0, 0.0));
            builder.setMesh(builder.addNode("LampPost_" + padded(lampIndex++, 4), t, lampsGroup), lampMesh);
        }

    // Parked cars along both kerbs, from 12 m inside the street ends (the eye-level cameras stand
    // 5 m inside them, so no car blocks their view down the street).
    const int carsGroup = builder.addNode("Cars", {});
    std::size_t carIndex = 0;
    for (int sideSign : {-1, 1}) {
        double z = -halfLength + 12.0 + carRandom.uniform(0.0, 10.0);
        while (z < halfLength - 12.0) {
            const std::uint32_t colour = carRandom.below(4);
            Transform t;
            t.translation = glm::dvec3(sideSign * 4.6, 0.02, z);
            builder.setMesh(builder.addNode("Car_" + padded(carIndex++, 4) + "_" + carNames[colour], t, carsGroup), carMeshes[colour]);
            z += carRandom.uniform(6.0, 30.0);
        }
    }

    // The sun 25 deg up, its light travelling down the street (-Z) and 8 deg across it: behind
    // a viewer at the start looking down the street, in front of one at the end looking back.
    const glm::dvec3 sunDirection = sunTravelDirection(25.0 * kDegree, -82.0 * kDegree);
    const int sun = builder.addDirectionalLight("Sun", {1.0, 0.95, 0.85}, 3.0);
    builder.addLightNode("Sun", sun, glm::dvec3(0.0, 200.0, 0.0) - 200.0 * sunDirection, sunDirection);

    const double far = length + 100.0;  // the whole street in view: a depth range of > 20,000 : 1
    const auto pitched = pitchedDirection;
    const std::vector<CameraPreset> presets = {
        {"Camera_DownStreet_SunBehind", {-2.0, 1.7, halfLength - 5.0}, pitched({0.0, 0.0, -1.0}, -1.0)},
        {"Camera_DownStreet_SunAhead", {2.0, 1.7, -halfLength + 5.0}, pitched({0.0, 0.0, 1.0}, -1.0)},
        {"Camera_Rooftop", {0.0, 40.0, halfLength - std::min(40.0, 0.2 * length)}, pitched({0.0, 0.0, -1.0}, -12.0)},
    };
    addCameraPresets(builder, presets, 0.1, far);
}

}  // namespace shadowlab::scenegen
