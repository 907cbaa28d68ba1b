// interior: a closed room modelled the way interiors for path tracers are: one shell of
// single-sided faces whose normals look inwards (floor, ceiling, four walls), open only at a
// window. A venetian blind of thin slats hangs inside the window, and the sun shines through it
// onto the floor, so the sun patch is striped; a table and chairs stand beside it, one chair in it.
// From the sun the shell's outer side is a back face: the scene that shows whether single-sided
// walls cast shadows.
#include "generators_internal.h"

#include <iterator>

namespace shadowlab::scenegen {

namespace {

// Inside of the room: x across, z from the window wall (z0) to the back wall (z1), y up.
constexpr float kX0 = -3.0f, kX1 = 3.0f, kZ0 = -2.5f, kZ1 = 2.5f, kHeight = 2.7f;
// The window opening in the wall z = kZ0.
constexpr float kWindowX0 = -1.0f, kWindowX1 = 1.0f, kWindowY0 = 0.9f, kWindowY1 = 2.2f;

struct Shell {
    MeshData floor, walls, ceiling;
};

// One shell, every face looking into the room. The window wall is the ring between its outer
// rectangle and the opening (four trapezoids), so its outer edges are not split and every edge of
// the shell meets exactly two triangles, except the opening's rim.
Shell roomShell() {
    Shell s;
    const glm::vec3 c000(kX0, 0, kZ0), c100(kX1, 0, kZ0), c110(kX1, kHeight, kZ0), c010(kX0, kHeight, kZ0);
    const glm::vec3 c001(kX0, 0, kZ1), c101(kX1, 0, kZ1), c111(kX1, kHeight, kZ1), c011(kX0, kHeight, kZ1);
    s.floor.addQuad(c000, c100, c101, c001, {0, 1, 0});
    s.ceiling.addQuad(c010, c110, c111, c011, {0, -1, 0});
    s.walls.addQuad(c001, c101, c111, c011, {0, 0, -1});  // back wall
    s.walls.addQuad(c000, c001, c011, c010, {1, 0, 0});   // left wall (x0)
    s.walls.addQuad(c100, c101, c111, c110, {-1, 0, 0});  // right wall (x1)
    const glm::vec3 outer[4] = {c000, c100, c110, c010};
    const glm::vec3 opening[4] = {{kWindowX0, kWindowY0, kZ0}, {kWindowX1, kWindowY0, kZ0},
                                  {kWindowX1, kWindowY1, kZ0}, {kWindowX0, kWindowY1, kZ0}};
    for (int i = 0; i < 4; ++i) s.walls.addQuad(outer[i], outer[(i + 1) % 4], opening[(i + 1) % 4], opening[i], {0, 0, 1});
    return s;
}

// Slats 6 cm deep and 3 mm thin, 9 cm apart, tilted 10 deg, hanging 8 cm inside the window
// under a head rail: about half of the sun passes between them (at the sun's 37 deg elevation in
// the blind's cross-section), striping the patch with a 13 cm period.
MeshData venetianBlind() {
    MeshData m;
    const float z = kZ0 + 0.08f;
    const float x0 = kWindowX0 - 0.05f, x1 = kWindowX1 + 0.05f;
    const MeshData slat = box({x0, -0.0015f, -0.03f}, {x1, 0.0015f, 0.03f});
    const glm::quat tilt = glm::angleAxis(float(10.0 * kDegree), glm::vec3(1, 0, 0));
    constexpr int kSlats = 14;  // from 5 cm below the opening's top down to 3 cm above its sill
    for (int i = 0; i < kSlats; ++i) m.append(slat, tilt, {0.0f, kWindowY1 - 0.05f - 0.09f * float(i), z});
    m.append(box({x0 - 0.03f, kWindowY1 + 0.01f, z - 0.035f}, {x1 + 0.03f, kWindowY1 + 0.06f, z + 0.035f}));
    return m;
}

// A table 1.4 x 0.8 m, 0.76 m high, origin on the floor under its centre.
MeshData table() {
    MeshData m = box({-0.7f, 0.72f, -0.4f}, {0.7f, 0.76f, 0.4f});
    for (float x : {-0.62f, 0.57f})
        for (float z : {-0.32f, 0.27f}) m.append(box({x, 0.0f, z}, {x + 0.05f, 0.72f, z + 0.05f}));
    return m;
}

// A chair facing +Z (its back on the -Z side), origin on the floor under the seat's centre.
MeshData chair() {
    MeshData m = box({-0.22f, 0.42f, -0.22f}, {0.22f, 0.46f, 0.22f});
    for (float x : {-0.21f, 0.17f})
        for (float z : {-0.21f, 0.17f}) m.append(box({x, 0.0f, z}, {x + 0.04f, 0.42f, z + 0.04f}));
    m.append(box({-0.22f, 0.46f, -0.22f}, {0.22f, 0.92f, -0.19f}));
    return m;
}

}  // namespace

void buildInterior(GltfBuilder& builder, const GenerateOptions&) {
    const int floorMaterial = builder.addMaterial("Floor_Oak", {0.45f, 0.30f, 0.17f, 1.0f}, 0.6f);
    const int wallMaterial = builder.addMaterial("Wall_Plaster", {0.80f, 0.78f, 0.72f, 1.0f});
    const int ceilingMaterial = builder.addMaterial("Ceiling_White", {0.90f, 0.90f, 0.88f, 1.0f});
    const int blindMaterial = builder.addMaterial("Blind_Aluminium", {0.70f, 0.72f, 0.74f, 1.0f}, 0.4f);
    const int woodMaterial = builder.addMaterial("Furniture_Walnut", {0.25f, 0.14f, 0.08f, 1.0f}, 0.5f);

    const Shell shell = roomShell();
    const int shellMesh = builder.addMesh(
        "Room_Shell", {{&shell.floor, floorMaterial}, {&shell.walls, wallMaterial}, {&shell.ceiling, ceilingMaterial}});
    const MeshData blind = venetianBlind();
    const int blindMesh = builder.addMesh("Venetian_Blind", {{&blind, blindMaterial}});
    const MeshData tableData = table(), chairData = chair();
    const int tableMesh = builder.addMesh("Table", {{&tableData, woodMaterial}});
    const int chairMesh = builder.addMesh("Chair", {{&chairData, woodMaterial}});

    builder.setMesh(builder.addNode("Room_Shell", {}), shellMesh);
    builder.setMesh(builder.addNode("Venetian_Blind", {}), blindMesh);
    const glm::dvec3 tableCentre(1.2, 0.0, 1.3);
    builder.setMesh(builder.addNode("Table", Transform{tableCentre}), tableMesh);
    // Three chairs at the table, out of the sun, each facing it, and one in the sun patch by the
    // window with its back to the room, throwing a striped shadow across the patch.
    struct Seat {
        glm::dvec3 position;
        double yawDeg;  // about +Y; 0 faces +Z
    };
    const Seat seats[] = {{tableCentre + glm::dvec3(0.0, 0.0, 0.72), 180.0},
                          {tableCentre + glm::dvec3(-1.0, 0.0, 0.0), 90.0},
                          {tableCentre + glm::dvec3(1.0, 0.0, 0.0), -90.0},
                          {{1.0, 0.0, -0.75}, 200.0}};
    const int chairsGroup = builder.addNode("Chairs", {});
    for (std::size_t i = 0; i < std::size(seats); ++i) {
        Transform t;
        t.translation = seats[i].position;
        t.rotation = glm::angleAxis(seats[i].yawDeg * kDegree, glm::dvec3(0.0, 1.0, 0.0));
        builder.setMesh(builder.addNode("Chair_" + padded(i, 2), t, chairsGroup), chairMesh);
    }

    // The sun 35 deg up, its light travelling into the room (+Z) and 20 deg across: the patch
    // falls on the floor 1.2 m .. 2.9 m from the window wall, clear of the table.
    const glm::dvec3 sunDirection = sunTravelDirection(35.0 * kDegree, 70.0 * kDegree);
    const glm::dvec3 windowCentre(0.5 * (kWindowX0 + kWindowX1), 0.5 * (kWindowY0 + kWindowY1), kZ0);
    const int sun = builder.addDirectionalLight("Sun", {1.0, 0.95, 0.85}, 3.0);
    builder.addLightNode("Sun", sun, windowCentre - 20.0 * sunDirection, sunDirection);

    const glm::dvec3 patchCentre(0.75, 0.0, -0.45);
    const std::vector<CameraPreset> presets = {
        {"Camera_SunPatch", {-2.4, 1.7, 1.9}, glm::normalize(patchCentre - glm::dvec3(-2.4, 1.7, 1.9))},
        {"Camera_Window", {-0.6, 1.6, 2.2}, glm::normalize(windowCentre - glm::dvec3(-0.6, 1.6, 2.2))},
        {"Camera_Wide", {2.7, 2.4, 2.2}, glm::normalize(glm::dvec3(-2.0, 0.6, -1.5) - glm::dvec3(2.7, 2.4, 2.2))},
    };
    addCameraPresets(builder, presets, 0.1, 30.0);
}

}  // namespace shadowlab::scenegen
