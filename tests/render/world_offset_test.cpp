// Large worlds keep sub-texel shadow precision. The plane-and-box scene moved
// 1e5 from the origin (camera and light with it) must show the same shadow as at the origin, for
// every method: the shadow and camera matrices go to the GPU relative to the camera
// (shaders/shadow_clip.glsl, forward.vert).
#include "render_helpers.h"
#include "test_scenes.h"

#include <cstdio>

namespace shadowlab::test {
namespace {

Scene offsetPlaneBox(glm::dvec3 offset) {
    Scene s;
    s.materials.push_back({"Ground", {0.8f, 0.8f, 0.8f, 1.0f}});
    s.materials.push_back({"Box", {0.8f, 0.1f, 0.1f, 1.0f}});
    // Geometry authored around its own origin and placed by the node transform, as glTF does.
    s.meshes.push_back({"Ground", {boxPrimitive({-10, -0.1f, -10}, {10, 0, 10}, 0)}});
    s.meshes.push_back({"Box", {boxPrimitive({-1, 0, -1}, {1, 2, 1}, 1)}});
    const glm::dmat4 place = glm::translate(glm::dmat4(1.0), offset);
    addInstance(s, 0, place);
    addInstance(s, 1, place);
    Light sun;
    sun.name = "Sun";
    sun.direction = glm::normalize(glm::dvec3(-0.3, -1.0, -0.2));
    s.lights.push_back(sun);
    return s;
}

class WorldOffset : public RenderTest {
protected:
    // Pixels whose shadow state (lit 0.9 vs shadowed 0.18 in the shadow-term view) differs.
    int shadowMismatches(ShadowMethod method, DepthOffset mode, glm::dvec3 offset) {
        const Scene here = offsetPlaneBox(glm::dvec3(0.0)), there = offsetPlaneBox(offset);
        Settings s = lookAt({4.0, 6.0, 9.0}, {0.0, 0.0, 0.0});
        s.method = method;
        s.viewMode = ViewMode::ShadowTermOnly;
        s.shadowMapSize = 2048;
        s.filter.filter = ShadowFilter::Nearest;
        s.bias.mode = mode;
        const RgbaImage a = render(here, s);
        Settings moved = s;
        moved.camera.position += offset;
        const RgbaImage b = render(there, moved);
        int differ = 0;
        for (int y = 0; y < a.height; ++y)
            for (int x = 0; x < a.width; ++x)
                differ += (luminance(a.at(x, y)) < 180.0) != (luminance(b.at(x, y)) < 180.0);
        return differ;
    }
};

TEST_F(WorldOffset, ShadowsAtOneHundredKilometresMatchTheOrigin) {
    const glm::dvec3 offset{1e5, 0.0, 1e5};
    for (DepthOffset mode : {DepthOffset::SlopeScale, DepthOffset::Adaptive})
        for (ShadowMethod m : {ShadowMethod::SsmFocused, ShadowMethod::Psm, ShadowMethod::Lispsm}) {
            const int differ = shadowMismatches(m, mode, offset);
            std::printf("%s, bias mode %d: %d of %d pixels differ in shadow state at a 1e5 offset\n", methodName(m),
                        int(mode), differ, kWidth * kHeight);
            // The lookup takes the eye-relative position (shadow_term.glsl): measured 0 for both
            // modes. From the interpolated world position, rounded to 8 mm steps at 1e5: 13 / 13 /
            // 20 (slope-scale), 319 / 319 / 317 (adaptive, whose margin is a fraction of a texel);
            // with world-space float matrices: 307, 307, 1449.
            EXPECT_LE(differ, kWidth * kHeight / 10000) << methodName(m) << " bias mode " << int(mode);
        }
}

}  // namespace
}  // namespace shadowlab::test
