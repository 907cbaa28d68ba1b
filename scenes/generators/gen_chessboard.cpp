// chessboard: the PSM paper's Fig. 1 - a chess board with its pieces lit by a spot light, seen
// from close by, where a uniform shadow map blurs the nearby pieces' shadows. A giant board
// (1 m squares, pieces 1 to 2 m tall) so the usual near plane of 0.1 m fits the close view.
// A fixed layout: the starting position; the seed does not change it.
#include "generators_internal.h"

namespace shadowlab::scenegen {

namespace {

// Profiles (radius, height) from the foot up, in metres for 1 m squares.
const std::vector<glm::vec2> kBase = {{0.0f, 0.0f}, {0.38f, 0.0f}, {0.38f, 0.08f}, {0.30f, 0.14f}};

std::vector<glm::vec2> withBase(std::initializer_list<glm::vec2> upper) {
    std::vector<glm::vec2> p = kBase;
    p.insert(p.end(), upper);
    return p;
}

MeshData pieceMesh(char kind) {
    constexpr int kSlices = 24;
    switch (kind) {
        case 'P':  // pawn: stem and ball
            return [&] {
                MeshData m = lathe(withBase({{0.16f, 0.45f}, {0.22f, 0.50f}, {0.0f, 0.52f}}), kSlices);
                m.append(ellipsoid({0.0f, 0.68f, 0.0f}, {0.17f, 0.17f, 0.17f}, kSlices, 12));
                return m;
            }();
        case 'R':  // rook: tower with a crenellated top
            return [&] {
                MeshData m = lathe(withBase({{0.24f, 0.80f}, {0.30f, 0.90f}, {0.30f, 1.10f}, {0.0f, 1.10f}}), kSlices);
                for (int i = 0; i < 4; ++i) {
                    const float a = float(i) * 1.5707963f;
                    const glm::vec3 c(0.22f * std::cos(a), 1.18f, 0.22f * std::sin(a));
                    m.append(box(c - glm::vec3(0.07f), c + glm::vec3(0.07f)));
                }
                return m;
            }();
        case 'N':  // knight: body and a box head leaning forward (+X)
            return [&] {
                MeshData m = lathe(withBase({{0.22f, 0.55f}, {0.0f, 0.60f}}), kSlices);
                m.append(box({-0.18f, 0.55f, -0.12f}, {0.12f, 1.15f, 0.12f}));
                m.append(box({0.0f, 0.90f, -0.10f}, {0.38f, 1.12f, 0.10f}));
                return m;
            }();
        case 'B':  // bishop: slim body and a mitre
            return lathe(withBase({{0.15f, 0.75f}, {0.24f, 0.82f}, {0.14f, 0.88f}, {0.20f, 1.15f}, {0.10f, 1.35f},
                                   {0.0f, 1.45f}}),
                         kSlices);
        case 'Q':  // queen: tall body, crown and ball
            return [&] {
                MeshData m = lathe(withBase({{0.17f, 1.00f}, {0.28f, 1.10f}, {0.18f, 1.18f}, {0.30f, 1.45f},
                                             {0.0f, 1.50f}}),
                                   kSlices);
                m.append(ellipsoid({0.0f, 1.60f, 0.0f}, {0.10f, 0.10f, 0.10f}, 16, 8));
                return m;
            }();
        default:  // 'K' king: tallest, with a cross
            return [&] {
                MeshData m = lathe(withBase({{0.18f, 1.10f}, {0.30f, 1.20f}, {0.20f, 1.28f}, {0.28f, 1.55f},
                                             {0.0f, 1.60f}}),
                                   kSlices);
                m.append(box({-0.05f, 1.60f, -0.05f}, {0.05f, 2.00f, 0.05f}));
                m.append(box({-0.16f, 1.78f, -0.05f}, {0.16f, 1.88f, 0.05f}));
                return m;
            }();
    }
}

const char* pieceName(char kind) {
    switch (kind) {
        case 'P': return "Pawn";
        case 'R': return "Rook";
        case 'N': return "Knight";
        case 'B': return "Bishop";
        case 'Q': return "Queen";
        default: return "King";
    }
}

}  // namespace

void buildChessboard(GltfBuilder& builder, const GenerateOptions&) {
    const int floorMaterial = builder.addMaterial("Floor", {0.45f, 0.45f, 0.47f, 1.0f});
    const int frameMaterial = builder.addMaterial("Board_Frame", {0.30f, 0.18f, 0.09f, 1.0f});
    const int lightSquares = builder.addMaterial("Board_Light", {0.85f, 0.78f, 0.60f, 1.0f});
    const int darkSquares = builder.addMaterial("Board_Dark", {0.22f, 0.12f, 0.06f, 1.0f});
    const int whiteMaterial = builder.addMaterial("Piece_White", {0.90f, 0.88f, 0.82f, 1.0f}, 0.5f);
    const int blackMaterial = builder.addMaterial("Piece_Black", {0.05f, 0.05f, 0.06f, 1.0f}, 0.5f);

    MeshData floor;
    floor.positions = {{-20, 0, -20}, {-20, 0, 20}, {20, 0, 20}, {20, 0, -20}};
    floor.normals.assign(4, glm::vec3(0, 1, 0));
    floor.indices = {0, 1, 2, 0, 2, 3};
    // The board: a 9 x 9 m frame 0.28 m high, the 8 x 8 squares as quads 2 cm above it.
    const MeshData frame = box({-4.5f, 0.0f, -4.5f}, {4.5f, 0.28f, 4.5f});
    constexpr float kTop = 0.30f;
    MeshData light, dark;
    for (int row = 0; row < 8; ++row)
        for (int col = 0; col < 8; ++col) {
            MeshData& m = (row + col) % 2 == 0 ? dark : light;  // a1 (row 0, col 0) is dark
            const float x0 = float(col) - 4.0f, z0 = 4.0f - float(row) - 1.0f;
            const auto base = std::uint32_t(m.positions.size());
            m.positions.insert(m.positions.end(), {{x0, kTop, z0}, {x0, kTop, z0 + 1}, {x0 + 1, kTop, z0 + 1}, {x0 + 1, kTop, z0}});
            m.normals.insert(m.normals.end(), 4, glm::vec3(0, 1, 0));
            m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        }
    const int floorMesh = builder.addMesh("Floor", {{&floor, floorMaterial}});
    const int boardMesh = builder.addMesh("Board", {{&frame, frameMaterial}, {&light, lightSquares}, {&dark, darkSquares}});
    builder.setMesh(builder.addNode("Floor", {}), floorMesh);
    builder.setMesh(builder.addNode("Board", {}), boardMesh);

    // One mesh per piece kind and colour.
    const std::string kinds = "PRNBQK";
    int meshes[2][6];
    for (std::size_t k = 0; k < kinds.size(); ++k) {
        const MeshData piece = pieceMesh(kinds[k]);
        meshes[0][k] = builder.addMesh(std::string(pieceName(kinds[k])) + "_White", {{&piece, whiteMaterial}});
        meshes[1][k] = builder.addMesh(std::string(pieceName(kinds[k])) + "_Black", {{&piece, blackMaterial}});
    }
    // Starting position; white on rows 1-2 (towards +Z, the main camera's side).
    const std::string backRank = "RNBQKBNR";
    const int piecesGroup = builder.addNode("Pieces", {});
    for (int colour = 0; colour < 2; ++colour)
        for (int rank : {0, 1})
            for (int file = 0; file < 8; ++file) {
                const char kind = rank == 0 ? backRank[std::size_t(file)] : 'P';
                const int row = colour == 0 ? rank : 7 - rank;
                const std::string square = std::string(1, char('a' + file)) + char('1' + row);
                Transform t;
                t.translation = glm::dvec3(file - 3.5, kTop, 3.5 - row);
                // Knights look across the board at the opponent (their head points along +X).
                if (kind == 'N') t.rotation = glm::angleAxis((colour == 0 ? 0.5 : -0.5) * std::numbers::pi, glm::dvec3(0, 1, 0));
                const std::size_t k = kinds.find(kind);
                builder.setMesh(builder.addNode(std::string(pieceName(kind)) + (colour == 0 ? "_White_" : "_Black_") + square, t,
                                                piecesGroup),
                                meshes[colour][k]);
            }

    // The spot light high to one side, aimed at the board's centre.
    const glm::dvec3 spotPosition(-6.0, 9.0, 5.0);
    const int spot = builder.addSpotLight("Spot", {1.0, 0.95, 0.85}, 800.0, 40.0, 32.0 * kDegree, 40.0 * kDegree);
    builder.addLightNode("Spot", spot, spotPosition, glm::dvec3(0.0, kTop, 0.0) - spotPosition);

    auto lookingAt = [](const char* name, glm::dvec3 eye, glm::dvec3 target) {
        return CameraPreset{name, eye, target - eye};
    };
    addCameraPresets(builder,
                     {
                         lookingAt("Camera_Main", {1.0, 2.4, 7.0}, {0.0, 0.5, 0.0}),         // over white's shoulder
                         lookingAt("Camera_Low", {-5.5, 1.1, 1.5}, {2.0, 0.6, -1.0}),        // along the board
                         lookingAt("Camera_FromLight", {-5.0, 7.5, 4.2}, {0.0, kTop, 0.0}),  // near the spot
                     },
                     0.1, 50.0);
}

}  // namespace shadowlab::scenegen
