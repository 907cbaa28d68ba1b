// The caster model (frame/caster_model.h): backdrop detection on scenes built in code, name
// patterns, and the ray-cast truth honouring the model's faces and exclusions.
#include "frame/caster_model.h"
#include "groundtruth/ray_scene.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>

namespace shadowlab {
namespace {

// Two triangles a b c, a c d (counter-clockwise seen from the side the front faces).
void addQuad(Primitive& p, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    const auto base = std::uint32_t(p.positions.size());
    for (const glm::vec3& v : {a, b, c, d}) {
        p.positions.push_back(v);
        p.bounds.extend(glm::dvec3(v));
    }
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) p.indices.push_back(base + i);
}

// A box whose faces look inward (a sky box): the outward box with every triangle reversed.
Primitive inwardBox(glm::vec3 lo, glm::vec3 hi) {
    Primitive p = test::boxPrimitive(lo, hi, 0);
    for (std::size_t i = 0; i + 2 < p.indices.size(); i += 3) std::swap(p.indices[i + 1], p.indices[i + 2]);
    return p;
}

// A room around the plane-and-box scene: floor, ceiling, four walls, and a window of 8 x 3 m in
// the wall at x = 12 (the walls face inward; what matters here is that rays pass the window).
Primitive roomWithWindow() {
    Primitive p;
    const float lo = -12.0f, hi = 12.0f, bottom = -1.0f, top = 6.0f;
    addQuad(p, {lo, bottom, lo}, {hi, bottom, lo}, {hi, bottom, hi}, {lo, bottom, hi});  // floor
    addQuad(p, {lo, top, lo}, {lo, top, hi}, {hi, top, hi}, {hi, top, lo});              // ceiling
    addQuad(p, {lo, bottom, lo}, {lo, bottom, hi}, {lo, top, hi}, {lo, top, lo});        // x = lo
    addQuad(p, {lo, bottom, lo}, {lo, top, lo}, {hi, top, lo}, {hi, bottom, lo});        // z = lo
    addQuad(p, {lo, bottom, hi}, {hi, bottom, hi}, {hi, top, hi}, {lo, top, hi});        // z = hi
    // x = hi around the window y 1.5 .. 4.5, z -4 .. 4.
    addQuad(p, {hi, bottom, lo}, {hi, 1.5f, lo}, {hi, 1.5f, hi}, {hi, bottom, hi});
    addQuad(p, {hi, 4.5f, lo}, {hi, top, lo}, {hi, top, hi}, {hi, 4.5f, hi});
    addQuad(p, {hi, 1.5f, lo}, {hi, 4.5f, lo}, {hi, 4.5f, -4.0f}, {hi, 1.5f, -4.0f});
    addQuad(p, {hi, 1.5f, 4.0f}, {hi, 4.5f, 4.0f}, {hi, 4.5f, hi}, {hi, 1.5f, hi});
    return p;
}

Scene withShell(Primitive shell, const char* name) {
    Scene s = test::planeBoxScene({-0.3, -1.0, -0.2});
    s.meshes.push_back({name, {std::move(shell)}});
    test::addInstance(s, int(s.meshes.size()) - 1, glm::dmat4(1.0));
    s.nodes.back().name = name;
    return s;
}

TEST(CasterModel, NamePatterns) {
    EXPECT_TRUE(namePatternMatches("SkyBox", "SkyBox"));
    EXPECT_TRUE(namePatternMatches("Sky*", "SkyBox"));
    EXPECT_TRUE(namePatternMatches("*Box", "SkyBox"));
    EXPECT_TRUE(namePatternMatches("S?y*x", "SkyBox"));
    EXPECT_TRUE(namePatternMatches("*", ""));
    EXPECT_TRUE(namePatternMatches("a*b*c", "axxbyyc"));
    EXPECT_FALSE(namePatternMatches("a*b*c", "axxbyy"));
    EXPECT_FALSE(namePatternMatches("sky*", "SkyBox"));  // case-sensitive, as glTF names are
    EXPECT_FALSE(namePatternMatches("", "SkyBox"));
    EXPECT_FALSE(namePatternMatches("Sky?", "Sky"));
}

TEST(CasterModel, FacesRule) {
    CasterModel m;
    m.singleSided = CasterFaces::Front;
    m.doubleSided = CasterFaces::Back;
    EXPECT_TRUE(m.triangleCasts(false, true));
    EXPECT_FALSE(m.triangleCasts(false, false));
    EXPECT_FALSE(m.triangleCasts(true, true));
    EXPECT_TRUE(m.triangleCasts(true, false));
    EXPECT_EQ(resolvedFaces(CasterFaces::Auto), CasterFaces::Both);
    EXPECT_EQ(resolvedFaces(CasterFaces::Back), CasterFaces::Back);
}

TEST(CasterModel, SkyBoxIsABackdropAndARoomWithAWindowIsNot) {
    const Scene sky = withShell(inwardBox({-40, -5, -40}, {40, 40, 40}), "SkyBox");
    EXPECT_EQ(detectBackdrops(sky), (std::vector<std::size_t>{2}));
    const Scene room = withShell(roomWithWindow(), "Room");
    EXPECT_TRUE(detectBackdrops(room).empty());
    // Without its window the room shuts out every sky direction: a backdrop by the rule.
    Primitive closed = roomWithWindow();
    addQuad(closed, {12, 1.5f, -4}, {12, 4.5f, -4}, {12, 4.5f, 4}, {12, 1.5f, 4});
    EXPECT_EQ(detectBackdrops(withShell(closed, "Closed")), (std::vector<std::size_t>{2}));
    // The plane-and-box scene alone has no shell, and a shell too big to test is left alone.
    EXPECT_TRUE(detectBackdrops(test::planeBoxScene()).empty());
    EXPECT_TRUE(detectBackdrops(sky, 4).empty());
}

TEST(CasterModel, BackdropExcludedUnlessIncludedOrDetectionOff) {
    const Scene sky = withShell(inwardBox({-40, -5, -40}, {40, 40, 40}), "SkyBox");
    const std::vector<std::size_t> backdrops = detectBackdrops(sky);
    CasterSettings settings;
    CasterChoice c = chooseCasters(sky, settings, backdrops);
    EXPECT_EQ(c.model.instanceCasts, (std::vector<std::uint8_t>{1, 1, 0}));
    ASSERT_EQ(c.notices.size(), 1u);
    EXPECT_NE(c.notices[0].find("'SkyBox'"), std::string::npos) << c.notices[0];
    EXPECT_NE(c.notices[0].find("casters.include"), std::string::npos) << c.notices[0];

    settings.include = {"Sky*"};
    c = chooseCasters(sky, settings, backdrops);
    EXPECT_TRUE(c.model.instanceCastsShadow(2));
    EXPECT_TRUE(c.notices.empty());

    settings.include.clear();
    settings.detectBackdrops = false;
    EXPECT_TRUE(chooseCasters(sky, settings, backdrops).model.instanceCastsShadow(2));

    settings.exclude = {"Box"};  // the mesh name of instance 1
    c = chooseCasters(sky, settings, backdrops);
    EXPECT_FALSE(c.model.instanceCastsShadow(1));
    EXPECT_TRUE(c.model.instanceCastsShadow(0));
    std::vector<std::uint32_t> casters{0, 1, 2};
    EXPECT_EQ(keepCasting(c.model, casters), 1u);
    EXPECT_EQ(casters, (std::vector<std::uint32_t>{0, 2}));
}

// The viewer's Ctrl+click: the nearest object under the ray switches its casting, and back.
TEST(CasterModel, PickedObjectSwitchesItsCasting) {
    const Scene sky = withShell(inwardBox({-40, -5, -40}, {40, 40, 40}), "SkyBox");
    const std::vector<std::size_t> backdrops = detectBackdrops(sky);
    EXPECT_EQ(pickInstance(sky, {0, 10, 0}, {0, -1, 0}), 1u);  // the box, above the ground
    EXPECT_EQ(pickInstance(sky, {5, 10, 5}, {0, -1, 0}), 0u);  // the ground beside it
    EXPECT_EQ(pickInstance(sky, {50, 10, 0}, {0, 1, 0}), SIZE_MAX);
    CasterSettings settings;
    toggleCasting(sky, 1, backdrops, settings);
    EXPECT_EQ(settings.exclude, (std::vector<std::string>{"node1"}));
    EXPECT_FALSE(chooseCasters(sky, settings, backdrops).model.instanceCastsShadow(1));
    toggleCasting(sky, 1, backdrops, settings);
    EXPECT_TRUE(settings.exclude.empty());
    // The backdrop casts only once named in include.
    const std::string said = toggleCasting(sky, 2, backdrops, settings);
    EXPECT_EQ(settings.include, (std::vector<std::string>{"SkyBox"})) << said;
    EXPECT_TRUE(chooseCasters(sky, settings, backdrops).model.instanceCastsShadow(2));
}

TEST(CasterModel, TruthSkipsTheExcludedBackdrop) {
    const Scene sky = withShell(inwardBox({-40, -5, -40}, {40, 40, 40}), "SkyBox");
    std::string error;
    auto rays = RayScene::build(sky, error);
    ASSERT_TRUE(rays) << error;
    ShadowLight sun;
    sun.kind = ShadowLightKind::Directional;
    sun.direction = glm::normalize(glm::dvec3(-0.3, -1.0, -0.2));
    const std::vector<RayReceiver> ground{{{5.0f, 0.0f, 5.0f}, {0, 1, 0}}, {{0.0f, 0.0f, 0.0f}, {0, 1, 0}}};
    // Every triangle casting: the sky box shadows everything.
    EXPECT_EQ(rays->visibleFromLight(ground, sun, CasterModel{}), (std::vector<std::uint8_t>{0, 0}));
    // The model with the backdrop out: open ground lit, under the box still dark.
    const CasterChoice c = chooseCasters(sky, CasterSettings{}, detectBackdrops(sky));
    EXPECT_EQ(rays->visibleFromLight(ground, sun, c.model), (std::vector<std::uint8_t>{1, 0}));
}

// A single-sided quad above the ground, its front facing down (the light sees its back): it casts
// under back and both, not under front, also through a mirroring node (det < 0), whose world-space
// winding reads the other way (glTF 2.0 3.7.4: clockwise is then the front).
TEST(CasterModel, TruthCastsTheFacesTheModelNames) {
    for (bool mirrored : {false, true}) {
        Scene s = test::planeBoxScene();
        Primitive quad;
        addQuad(quad, {-1, 3, -1}, {1, 3, -1}, {1, 3, 1}, {-1, 3, 1});  // counter-clockwise from below: faces down
        s.meshes[1] = {"Quad", {quad}};
        s.instances.pop_back();
        s.nodes.pop_back();
        test::addInstance(s, 1, mirrored ? glm::scale(glm::dmat4(1.0), glm::dvec3(-1, 1, 1)) : glm::dmat4(1.0));
        std::string error;
        auto rays = RayScene::build(s, error);
        ASSERT_TRUE(rays) << error;
        ShadowLight sun;
        sun.kind = ShadowLightKind::Directional;
        sun.direction = {0.0, -1.0, 0.0};
        // Mirrored or not, the front is the down side (the normal matrix keeps y), though under the
        // mirror the world-space vertices wind counter-clockwise seen from above.
        const bool frontFacesLight = false;
        for (CasterFaces faces : {CasterFaces::Front, CasterFaces::Back, CasterFaces::Both}) {
            CasterModel model;
            model.singleSided = faces;
            const auto lit = rays->visibleFromLight({{{0.2f, 0.0f, 0.1f}, {0, 1, 0}}}, sun, model);
            EXPECT_EQ(lit[0] == 0, model.triangleCasts(false, frontFacesLight))
                << "mirrored " << mirrored << ", faces " << int(faces);
        }
    }
}

}  // namespace
}  // namespace shadowlab
