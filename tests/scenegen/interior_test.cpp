// The closed interior (generate interior) and the sky box any scene can be wrapped in (--skybox):
// shells closed and facing inwards, cameras inside, the sun striped by the blind on the floor, and
// a sky box that encloses the scene it wraps without changing anything else.
#include "gltf_inspect.h"
#include "scenes/generators/scene_generators.h"
#include "scenes/image_decode.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <map>
#include <optional>
#include <tuple>

namespace shadowlab::test {
namespace {

namespace fs = std::filesystem;
using scenegen::GenerateOptions;
using scenegen::GenerateResult;
using Triangle = std::array<glm::dvec3, 3>;

fs::path tempDir() {
    const fs::path dir = fs::path(::testing::TempDir()) / ("shadowlab_interior_tests_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    static const struct Cleanup {
        fs::path path;
        ~Cleanup() {
            std::error_code ignored;
            fs::remove_all(path, ignored);
        }
    } cleanup{dir};
    return dir;
}

struct Generated {
    GenerateResult result;
    fs::path file;
    Inspected inspected;
};

// Generated once per (name, scale, sky box) for the whole suite.
const Generated& scene(const std::string& name, bool skyBox, double scale = 1.0) {
    static std::map<std::tuple<std::string, bool, double>, Generated> cache;
    const auto key = std::make_tuple(name, skyBox, scale);
    if (auto it = cache.find(key); it != cache.end()) return it->second;
    Generated g;
    g.file = tempDir() / (name + (skyBox ? "-skybox-" : "-") + std::to_string(scale) + ".glb");
    GenerateOptions options;
    options.scale = scale;
    options.skyBox = skyBox;
    g.result = scenegen::generateScene(name, options, g.file);
    if (g.result.ok) g.inspected = inspect(g.file);
    return cache.emplace(key, std::move(g)).first->second;
}

// World-space triangles of every mesh node, or only of the node called `only`.
std::vector<Triangle> worldTriangles(const Inspected& f, const std::string& only = {}) {
    std::vector<Triangle> out;
    for (const InspectedNode& n : f.nodes) {
        if (n.mesh < 0 || (!only.empty() && n.name != only)) continue;
        for (const tinygltf::Primitive& p : f.model.meshes[std::size_t(n.mesh)].primitives) {
            const auto pos = readVec3(f.model, p.attributes.at("POSITION"));
            const auto idx = readIndices(f.model, p.indices);
            for (std::size_t t = 0; t + 2 < idx.size(); t += 3) {
                Triangle tri;
                for (std::size_t k = 0; k < 3; ++k)
                    tri[k] = glm::dvec3(n.world * glm::dvec4(glm::dvec3(pos[idx[t + k]]), 1.0));
                out.push_back(tri);
            }
        }
    }
    return out;
}

glm::dvec3 faceNormal(const Triangle& t) { return glm::normalize(glm::cross(t[1] - t[0], t[2] - t[0])); }
glm::dvec3 centroid(const Triangle& t) { return (t[0] + t[1] + t[2]) / 3.0; }

// Directed edges after welding equal positions (primitives and faces do not share vertices):
// a closed, consistently wound surface has every edge once in each direction.
struct EdgeUse {
    int forward = 0, backward = 0;  // from the lower to the higher point id, and back
};
struct Edges {
    std::vector<glm::dvec3> points;  // by id
    std::map<std::pair<std::size_t, std::size_t>, EdgeUse> uses;
};
Edges edgeUses(const std::vector<Triangle>& triangles) {
    auto less = [](const glm::dvec3& a, const glm::dvec3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); };
    std::map<glm::dvec3, std::size_t, decltype(less)> ids(less);
    Edges edges;
    auto id = [&](const glm::dvec3& p) {
        const auto [it, added] = ids.emplace(p, ids.size());
        if (added) edges.points.push_back(p);
        return it->second;
    };
    for (const Triangle& t : triangles)
        for (int k = 0; k < 3; ++k) {
            const std::size_t a = id(t[std::size_t(k)]), b = id(t[std::size_t((k + 1) % 3)]);
            if (a < b)
                ++edges.uses[{a, b}].forward;
            else
                ++edges.uses[{b, a}].backward;
        }
    return edges;
}

std::optional<double> rayHit(const glm::dvec3& origin, const glm::dvec3& direction, const Triangle& t) {
    // Moeller-Trumbore, both sides.
    const glm::dvec3 e1 = t[1] - t[0], e2 = t[2] - t[0], p = glm::cross(direction, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-14) return std::nullopt;
    const glm::dvec3 s = origin - t[0];
    const double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) return std::nullopt;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(direction, q) / det;
    if (v < 0.0 || u + v > 1.0) return std::nullopt;
    const double d = glm::dot(e2, q) / det;
    return d > 1e-6 ? std::optional<double>(d) : std::nullopt;
}

bool blocked(const std::vector<Triangle>& triangles, const glm::dvec3& origin, const glm::dvec3& direction) {
    for (const Triangle& t : triangles)
        if (rayHit(origin, direction, t)) return true;
    return false;
}

// The room's inside as the file describes it: the bounds of the shell.
void shellBounds(const std::vector<Triangle>& shell, glm::dvec3& lo, glm::dvec3& hi) {
    lo = glm::dvec3(1e30), hi = glm::dvec3(-1e30);
    for (const Triangle& t : shell)
        for (const glm::dvec3& p : t) lo = glm::min(lo, p), hi = glm::max(hi, p);
}

// The shell's open edges (used by one triangle): their bounds and total length. `closedOk` is
// false when an edge is used by more than two triangles or twice in the same direction.
struct OpenEdges {
    glm::dvec3 lo{1e30}, hi{-1e30};
    double length = 0.0;
    std::size_t count = 0, shared = 0;
    bool closedOk = true;
};
OpenEdges openEdges(const std::vector<Triangle>& triangles) {
    const Edges edges = edgeUses(triangles);
    OpenEdges open;
    for (const auto& [edge, use] : edges.uses) {
        if (use.forward == 1 && use.backward == 1) {
            ++open.shared;
            continue;
        }
        if (use.forward + use.backward != 1) open.closedOk = false;
        const glm::dvec3 a = edges.points[edge.first], b = edges.points[edge.second];
        ++open.count;
        open.length += glm::distance(a, b);
        open.lo = glm::min(open.lo, glm::min(a, b));
        open.hi = glm::max(open.hi, glm::max(a, b));
    }
    return open;
}

// ---------- interior ----------

TEST(InteriorScene, ShellIsClosedAndConsistentlyWoundExceptTheWindowRim) {
    const Generated& g = scene("interior", false);
    ASSERT_TRUE(g.result.ok) << g.result.error;
    const auto shell = worldTriangles(g.inspected, "Room_Shell");
    ASSERT_FALSE(shell.empty());
    glm::dvec3 lo, hi;
    shellBounds(shell, lo, hi);
    const OpenEdges open = openEdges(shell);
    EXPECT_TRUE(open.closedOk) << "an edge used by more than two triangles, or twice the same way";
    EXPECT_GE(open.shared, 18u);
    // The open edges are exactly one rectangle in the wall z = lo.z, away from the room's corners:
    // the window opening.
    EXPECT_EQ(open.count, 4u);
    EXPECT_EQ(open.lo.z, lo.z);
    EXPECT_EQ(open.hi.z, lo.z);
    EXPECT_NEAR(open.length, 2.0 * ((open.hi.x - open.lo.x) + (open.hi.y - open.lo.y)), 1e-6);
    EXPECT_GT(open.hi.x - open.lo.x, 1.0);
    EXPECT_GT(open.hi.y - open.lo.y, 1.0);
    EXPECT_GT(open.lo.x, lo.x + 0.5);
    EXPECT_LT(open.hi.x, hi.x - 0.5);
    EXPECT_GT(open.lo.y, lo.y + 0.5);
    EXPECT_LT(open.hi.y, hi.y - 0.3);
}

TEST(InteriorScene, ShellIsSingleSidedWithEveryFaceLookingIntoTheRoom) {
    const Generated& g = scene("interior", false);
    ASSERT_TRUE(g.result.ok) << g.result.error;
    const auto shell = worldTriangles(g.inspected, "Room_Shell");
    glm::dvec3 lo, hi;
    shellBounds(shell, lo, hi);
    const glm::dvec3 centre = (lo + hi) * 0.5;
    for (const Triangle& t : shell) EXPECT_GT(glm::dot(faceNormal(t), centre - centroid(t)), 0.5) << "a shell face looks out";
    const tinygltf::Model& m = g.inspected.model;
    for (const tinygltf::Primitive& p : m.meshes[std::size_t(g.inspected.node("Room_Shell")->mesh)].primitives)
        EXPECT_FALSE(m.materials[std::size_t(p.material)].doubleSided) << m.materials[std::size_t(p.material)].name;
    // Furniture and blind are inside the shell.
    EXPECT_EQ(g.inspected.lo, lo);
    EXPECT_EQ(g.inspected.hi, hi);
}

TEST(InteriorScene, CamerasStandInsideTheRoomAndOneSeesTheSunPatch) {
    const Generated& g = scene("interior", false);
    ASSERT_TRUE(g.result.ok) << g.result.error;
    const Inspected& f = g.inspected;
    const auto shell = worldTriangles(f, "Room_Shell");
    glm::dvec3 lo, hi;
    shellBounds(shell, lo, hi);
    std::size_t cameras = 0;
    for (const InspectedNode& n : f.nodes) {
        if (n.camera < 0) continue;
        ++cameras;
        for (int i = 0; i < 3; ++i) {
            // Clear of the walls by more than the near plane's reach (0.1 m, fov 60 at 16:9: < 0.15 m).
            EXPECT_GT(n.position()[i], lo[i] + 0.2) << n.name;
            EXPECT_LT(n.position()[i], hi[i] - 0.2) << n.name;
        }
    }
    EXPECT_GE(cameras, 2u);
    EXPECT_LE(cameras, 3u);
    // Where the sun through the middle of the opening meets the floor, inside the SunPatch view.
    const glm::dvec3 sun = f.node("Sun")->forward();
    const OpenEdges window = openEdges(shell);
    const glm::dvec3 windowMiddle = (window.lo + window.hi) * 0.5;
    const glm::dvec3 patch = windowMiddle + sun * ((lo.y - windowMiddle.y) / sun.y);
    const InspectedNode* cam = f.node("Camera_SunPatch");
    ASSERT_NE(cam, nullptr);
    EXPECT_GT(glm::dot(glm::normalize(patch - cam->position()), cam->forward()), std::cos(25.0 * 3.14159265 / 180.0));
    EXPECT_NE(f.node("Camera_Window"), nullptr);
}

TEST(InteriorScene, SunEntersOnlyThroughTheWindowAndTheBlindStripesThePatch) {
    const Generated& g = scene("interior", false);
    ASSERT_TRUE(g.result.ok) << g.result.error;
    const Inspected& f = g.inspected;
    const auto all = worldTriangles(f), shell = worldTriangles(f, "Room_Shell");
    glm::dvec3 lo, hi;
    shellBounds(shell, lo, hi);
    const glm::dvec3 sun = f.node("Sun")->forward();
    EXPECT_LT(sun.y, -0.3) << "the sun shines down";
    EXPECT_GT(sun.z, 0.5) << "into the room through the window wall (z = lo.z)";
    // Walk the floor from the window wall along the sun's horizontal direction, below the
    // opening's middle: lit points are only where the ray to the sun passes the opening, and the
    // slats cut the lit run into stripes.
    const OpenEdges window = openEdges(shell);
    const glm::dvec3 along = glm::normalize(glm::dvec3(sun.x, 0.0, sun.z));
    const glm::dvec3 start((window.lo.x + window.hi.x) * 0.5, lo.y + 1e-4, lo.z + 0.01);
    int lit = 0, changes = 0;
    bool previous = false;
    std::size_t samples = 0;
    for (double s = 0.0; s < 6.0; s += 0.005, ++samples) {
        const glm::dvec3 p = start + along * s;
        if (p.z >= hi.z) break;
        const bool isLit = !blocked(all, p, -sun);
        // Without the blind and furniture, is the point in the window's light?
        const bool throughOpening = !blocked(shell, p, -sun);
        EXPECT_TRUE(!isLit || throughOpening) << "light at " << p.x << ", " << p.z << " that no opening lets in";
        lit += isLit;
        if (samples > 0 && isLit != previous) ++changes;
        previous = isLit;
    }
    EXPECT_GT(lit, 40) << "a sun patch on the floor";
    EXPECT_GE(changes, 16) << "the blind's slats stripe the patch";
}

// ---------- sky box ----------

class SkyBox : public ::testing::TestWithParam<std::string> {};

TEST_P(SkyBox, EnclosesTheSceneItsCamerasAndLightsAndFacesInwards) {
    const double scale = GetParam() == "street" ? 0.1 : 1.0;
    const Generated& plain = scene(GetParam(), false, scale);
    const Generated& boxed = scene(GetParam(), true, scale);
    ASSERT_TRUE(plain.result.ok && boxed.result.ok) << plain.result.error << boxed.result.error;
    const Inspected &a = plain.inspected, &b = boxed.inspected;
    // Everything else is unchanged: one more node, mesh, material and 12 triangles.
    EXPECT_EQ(b.model.nodes.size(), a.model.nodes.size() + 1);
    EXPECT_EQ(b.model.meshes.size(), a.model.meshes.size() + 1);
    EXPECT_EQ(b.model.materials.size(), a.model.materials.size() + 1);
    EXPECT_EQ(b.triangles, a.triangles + 12);
    for (std::size_t i = 0; i < a.model.nodes.size(); ++i) EXPECT_TRUE(a.model.nodes[i] == b.model.nodes[i]) << a.model.nodes[i].name;
    EXPECT_EQ(boxed.result.stats.cameras, plain.result.stats.cameras);

    const auto box = worldTriangles(b, "SkyBox");
    ASSERT_EQ(box.size(), 12u);
    for (const auto& [edge, use] : edgeUses(box).uses)
        EXPECT_TRUE(use.forward == 1 && use.backward == 1) << "the sky box is closed and consistently wound";
    glm::dvec3 lo, hi;
    shellBounds(box, lo, hi);
    const glm::dvec3 centre = (lo + hi) * 0.5;
    for (const Triangle& t : box) EXPECT_GT(glm::dot(faceNormal(t), centre - centroid(t)), 0.0) << "faces look inwards";
    // Encloses everything the plain scene draws, its cameras and its positioned lights, with room.
    auto inside = [&](const glm::dvec3& p) {
        return glm::all(glm::greaterThan(p, lo + 1.0)) && glm::all(glm::lessThan(p, hi - 1.0));
    };
    EXPECT_TRUE(inside(a.lo) && inside(a.hi)) << "drawn bounds";
    for (const InspectedNode& n : a.nodes) {
        const bool positioned = n.camera >= 0 || (n.light >= 0 && a.model.lights[std::size_t(n.light)].type != "directional");
        EXPECT_TRUE(!positioned || inside(n.position())) << n.name;
    }
}

TEST_P(SkyBox, IsOneSingleSidedMaterialWithASmallEmbeddedPngTexture) {
    const double scale = GetParam() == "street" ? 0.1 : 1.0;
    const Generated& boxed = scene(GetParam(), true, scale);
    ASSERT_TRUE(boxed.result.ok) << boxed.result.error;
    const tinygltf::Model& m = boxed.inspected.model;
    const InspectedNode* node = boxed.inspected.node("SkyBox");
    ASSERT_NE(node, nullptr);
    const tinygltf::Mesh& mesh = m.meshes[std::size_t(node->mesh)];
    ASSERT_EQ(mesh.primitives.size(), 1u);
    const tinygltf::Primitive& p = mesh.primitives[0];
    const tinygltf::Material& material = m.materials[std::size_t(p.material)];
    EXPECT_FALSE(material.doubleSided);
    ASSERT_TRUE(p.attributes.count("TEXCOORD_0"));
    const tinygltf::Accessor& uv = m.accessors[std::size_t(p.attributes.at("TEXCOORD_0"))];
    EXPECT_EQ(uv.type, TINYGLTF_TYPE_VEC2);
    EXPECT_EQ(uv.count, m.accessors[std::size_t(p.attributes.at("POSITION"))].count);
    const int textureIndex = material.pbrMetallicRoughness.baseColorTexture.index;
    ASSERT_GE(textureIndex, 0);
    const tinygltf::Image& image = m.images[std::size_t(m.textures[std::size_t(textureIndex)].source)];
    EXPECT_EQ(image.mimeType, "image/png");
    EXPECT_TRUE(image.uri.empty()) << "embedded in the GLB's buffer";
    ASSERT_GE(image.bufferView, 0);
    const tinygltf::BufferView& view = m.bufferViews[std::size_t(image.bufferView)];
    const auto& data = m.buffers[std::size_t(view.buffer)].data;
    const std::vector<std::uint8_t> png(data.begin() + std::ptrdiff_t(view.byteOffset),
                                        data.begin() + std::ptrdiff_t(view.byteOffset + view.byteLength));
    EXPECT_LT(png.size(), 20000u) << "a small texture";
    int w = 0, h = 0;
    std::vector<std::uint8_t> rgba;
    std::string reason;
    ASSERT_TRUE(decoder::decodeRgba8(png, w, h, rgba, reason)) << reason;
    EXPECT_EQ(w, 64);
    EXPECT_EQ(h, 64);
    // Sky above (blue over red), ground below.
    EXPECT_GT(rgba[2], rgba[0]);
    EXPECT_LT(rgba[std::size_t((63 * 64) * 4 + 2)], rgba[2]);
}

INSTANTIATE_TEST_SUITE_P(Scenes, SkyBox, ::testing::Values("interior", "plane-box", "chessboard", "street"),
                         [](const auto& info) {
                             std::string n = info.param;
                             std::replace(n.begin(), n.end(), '-', '_');
                             return n;
                         });

TEST(SkyBoxOption, SameOptionsGiveByteIdenticalFiles) {
    const Generated& first = scene("interior", true);
    ASSERT_TRUE(first.result.ok) << first.result.error;
    const fs::path again = tempDir() / "interior-skybox-again.glb";
    GenerateOptions options;
    options.skyBox = true;
    ASSERT_TRUE(scenegen::generateScene("interior", options, again).ok);
    EXPECT_TRUE(readBytes(first.file) == readBytes(again));
}

}  // namespace
}  // namespace shadowlab::test
