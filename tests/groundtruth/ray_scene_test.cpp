// Embree visibility toward the light on scenes built in code: named geometric cases.
#include "groundtruth/ray_scene.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

namespace shadowlab {
namespace {

ShadowLight sunTravelling(glm::dvec3 direction) {
    ShadowLight l;
    l.kind = ShadowLightKind::Directional;
    l.direction = glm::normalize(direction);
    return l;
}

RayReceiver onGround(float x, float z) { return {{x, 0.0f, z}, {0.0f, 1.0f, 0.0f}}; }

const CasterModel kEveryCaster{};  // every triangle, both sides: the truth before a caster model

std::unique_ptr<RayScene> build(const Scene& scene) {
    std::string error;
    auto rs = RayScene::build(scene, error);
    EXPECT_TRUE(rs) << error;
    return rs;
}

TEST(RayScene, GroundUnderTheBoxIsShadowedAndOpenGroundLit) {
    const Scene scene = test::planeBoxScene({0, -1, 0});
    auto rs = build(scene);
    ASSERT_TRUE(rs);
    EXPECT_EQ(rs->triangleCount(), 24u);
    const auto lit = rs->visibleFromLight({onGround(0, 0), onGround(0.9f, -0.9f), onGround(5, 5), onGround(1.1f, 0)},
                                          sunTravelling({0, -1, 0}), kEveryCaster, 2);
    EXPECT_EQ(lit, (std::vector<std::uint8_t>{0, 0, 1, 1}));
}

TEST(RayScene, SlantedSunMovesTheShadow) {
    // Light travelling toward +x at 45 degrees: the 2 m box shadows the ground from x = 1 to 3.
    const Scene scene = test::planeBoxScene();
    auto rs = build(scene);
    ASSERT_TRUE(rs);
    const auto lit = rs->visibleFromLight({onGround(2.5f, 0), onGround(3.5f, 0), onGround(-1.5f, 0)},
                                          sunTravelling({1, -1, 0}), kEveryCaster);
    EXPECT_EQ(lit, (std::vector<std::uint8_t>{0, 1, 1}));
}

TEST(RayScene, ReceiverOnTheCasterTopIsLitNotSelfShadowed) {
    const Scene scene = test::planeBoxScene({0, -1, 0});
    auto rs = build(scene);
    ASSERT_TRUE(rs);
    // The box's top face at y = 2: the offset origin must not hit its own triangle.
    const auto lit = rs->visibleFromLight({{{0.3f, 2.0f, -0.2f}, {0, 1, 0}}}, sunTravelling({0, -1, 0}), kEveryCaster);
    EXPECT_EQ(lit[0], 1);
}

TEST(RayScene, SpotSegmentEndsAtTheLight) {
    const Scene scene = test::planeBoxScene({0, -1, 0});
    auto rs = build(scene);
    ASSERT_TRUE(rs);
    ShadowLight spot;
    spot.kind = ShadowLightKind::Spot;
    spot.direction = {0, -1, 0};
    spot.position = {0, 1.5, 0};  // inside the box: everything outside is shadowed by its walls ...
    const auto inside = rs->visibleFromLight({onGround(5, 0)}, spot, kEveryCaster);
    EXPECT_EQ(inside[0], 0);
    spot.position = {5, 1.0, 0};  // ... a spot beside the box lights the ground below it
    const auto beside = rs->visibleFromLight({onGround(5, 0), onGround(-2, 0)}, spot, kEveryCaster);
    EXPECT_EQ(beside, (std::vector<std::uint8_t>{1, 0}));
}

// A 2 x 2 quad at height 1 whose texture is transparent in its left half (u < 0.5), MASK material.
Scene maskedQuadScene(AlphaMode mode) {
    Scene s;
    Texture t;
    t.width = 4;
    t.height = 1;
    t.sampler.wrapS = t.sampler.wrapT = 33071;
    t.rgba8.assign(16, 255);
    t.rgba8[3] = t.rgba8[7] = 0;  // alpha of texels 0 and 1
    s.textures.push_back(t);
    Material m;
    m.baseColorTexture = 0;
    m.alphaMode = mode;
    m.alphaCutoff = 0.5f;
    s.materials.push_back(m);
    Primitive p;
    p.positions = {{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}};
    p.normals.assign(4, {0, 1, 0});
    p.texcoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    p.indices = {0, 2, 1, 0, 3, 2};
    p.material = 0;
    for (const glm::vec3& v : p.positions) p.bounds.extend(glm::dvec3(v));
    s.meshes.push_back({"Quad", {p}});
    test::addInstance(s, 0, glm::dmat4(1.0));
    return s;
}

TEST(RayScene, AlphaMaskedTrianglesLetLightThroughTheirHoles) {
    const Scene scene = maskedQuadScene(AlphaMode::Mask);
    auto rs = build(scene);
    ASSERT_TRUE(rs);
    const auto lit = rs->visibleFromLight({onGround(-0.6f, 0.3f), onGround(0.6f, 0.3f), onGround(-0.6f, -0.7f)},
                                          sunTravelling({0, -1, 0}), kEveryCaster);
    EXPECT_EQ(lit, (std::vector<std::uint8_t>{1, 0, 1}));
}

TEST(RayScene, OpaqueAndBlendedSurfacesBlockFully) {
    for (AlphaMode mode : {AlphaMode::Opaque, AlphaMode::Blend}) {
        const Scene scene = maskedQuadScene(mode);
        auto rs = build(scene);
        ASSERT_TRUE(rs);
        const auto lit = rs->visibleFromLight({onGround(-0.6f, 0.3f)}, sunTravelling({0, -1, 0}), kEveryCaster);
        EXPECT_EQ(lit[0], 0) << int(mode);
    }
}

TEST(RayScene, EmptySceneLightsEverything) {
    Scene empty;
    auto rs = build(empty);
    ASSERT_TRUE(rs);
    EXPECT_EQ(rs->triangleCount(), 0u);
    EXPECT_EQ(rs->visibleFromLight({onGround(0, 0)}, sunTravelling({0, -1, 0}), kEveryCaster)[0], 1);
    EXPECT_TRUE(rs->visibleFromLight({}, sunTravelling({0, -1, 0}), kEveryCaster).empty());
}

}  // namespace
}  // namespace shadowlab
