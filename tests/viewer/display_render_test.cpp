// The lit view's display end through a headless EGL context (llvmpipe on CI): the tone-mapping
// operators on known values, the edge-aware blur not crossing a depth edge, and no shadow-test
// hatching on facets that face away from the light (thesis 6.2).
#include "gl/program.h"
#include "frame/ground_plane.h"
#include "render_helpers.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace shadowlab::test {
namespace {

class DisplayRender : public RenderTest {
protected:
    // toneMap(input) as the forward shader computes it, read back without the sRGB encode.
    glm::dvec3 toneMapOnGpu(glm::dvec3 input, ToneMapping op, double exposureEv) {
        std::string error;
        auto program = gl::Program::build("fullscreen.vert", "tone_mapping_check.frag", "", error);
        EXPECT_TRUE(program) << error;
        if (!program) return glm::dvec3(-1.0);
        RenderTarget target(4, 4);
        gl::VertexArray vao = gl::createVertexArray();
        program->use();
        program->set("uInput", glm::vec3(input));
        program->set("uToneMapping", int(op));
        program->set("uExposure", float(std::exp2(exposureEv)));
        glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
        glViewport(0, 0, 4, 4);
        glDisable(GL_FRAMEBUFFER_SRGB);
        glBindVertexArray(vao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
        glUseProgram(0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        const glm::u8vec4 p = target.readColor().at(1, 1);
        return glm::dvec3(p) / 255.0;
    }
};

TEST_F(DisplayRender, ToneMappingOperatorsOnKnownValues) {
    constexpr double kTol = 1.5 / 255.0;
    // None: linear, only the exposure (2^EV) applies.
    EXPECT_NEAR(toneMapOnGpu(glm::dvec3(0.5), ToneMapping::None, 0.0).r, 0.5, kTol);
    EXPECT_NEAR(toneMapOnGpu(glm::dvec3(0.25), ToneMapping::None, 1.0).r, 0.5, kTol);
    // Khronos PBR Neutral: below the compression start only the 0.04 offset (0.5 -> 0.46); white
    // 1.0 -> 1 - 0.24^2 / 0.44 = 0.869; grey stays grey; very bright approaches 1 without clipping.
    EXPECT_NEAR(toneMapOnGpu(glm::dvec3(0.5), ToneMapping::PbrNeutral, 0.0).r, 0.46, kTol);
    const glm::dvec3 white = toneMapOnGpu(glm::dvec3(1.0), ToneMapping::PbrNeutral, 0.0);
    EXPECT_NEAR(white.r, 1.0 - 0.24 * 0.24 / 0.44, kTol);
    EXPECT_NEAR(white.g, white.r, 1e-9);
    EXPECT_NEAR(white.b, white.r, 1e-9);
    EXPECT_NEAR(toneMapOnGpu(glm::dvec3(0.0), ToneMapping::PbrNeutral, 0.0).r, 0.0, kTol);
    const double bright = toneMapOnGpu(glm::dvec3(50.0), ToneMapping::PbrNeutral, 0.0).r;
    EXPECT_GT(bright, 0.99);
    // ACES (Narkowicz): 1.0 -> 2.54 / 3.16; EV +1 on 0.5 gives the same.
    EXPECT_NEAR(toneMapOnGpu(glm::dvec3(1.0), ToneMapping::Aces, 0.0).r, 2.54 / 3.16, kTol);
    EXPECT_NEAR(toneMapOnGpu(glm::dvec3(0.5), ToneMapping::Aces, 1.0).r, 2.54 / 3.16, kTol);
}

TEST_F(DisplayRender, EdgeAwareBlurDoesNotCarryShadowAcrossADepthEdge) {
    // Sun from above and in front: the box's shadow falls on the ground behind it. Seen from the
    // front and above, the lit box top borders that shadow along its back edge, a depth edge. The
    // plain blur darkens the top near the edge; the edge-aware blur leaves it as lit as its middle.
    const Scene scene = planeBoxScene({0.0, -1.0, -1.5});  // a 3 m shadow behind the 2 m box
    Settings s = lookAt({0.0, 10.0, 4.0}, {0.0, 0.0, -2.0});
    s.viewMode = ViewMode::ShadowTermOnly;
    s.filter.blurIterations = 4;
    s.filter.blurStrength = 3.0;
    const glm::ivec2 nearEdge = project(s, kWidth, kHeight, {0.0, 2.0, -0.93});
    const glm::ivec2 middle = project(s, kWidth, kHeight, {0.0, 2.0, 0.2});
    const glm::ivec2 shadowed = project(s, kWidth, kHeight, {0.0, 0.0, -3.0});
    s.filter.edgeAwareBlur = true;
    const RgbaImage aware = render(scene, s);
    s.filter.edgeAwareBlur = false;
    const RgbaImage plain = render(scene, s);
    // The ground behind really is in shadow, the top really lit.
    EXPECT_LT(luminance(aware.at(shadowed.x, shadowed.y)) + 60, luminance(aware.at(middle.x, middle.y)));
    EXPECT_NEAR(luminance(aware.at(nearEdge.x, nearEdge.y)), luminance(aware.at(middle.x, middle.y)), 6.0);
    // The same place under the plain Gaussian: shadow bled onto the top (the test can fail).
    EXPECT_LT(luminance(plain.at(nearEdge.x, nearEdge.y)) + 10, luminance(plain.at(middle.x, middle.y)));
}

TEST_F(DisplayRender, FacetsFacingAwayFromTheLightAreNotShadowTested) {
    // The box with smooth (radial) normals, the sun high and slightly towards -z: the back face
    // (normal -z) faces away from the light, but its interpolated normals tilt up, so N.L > 0 on
    // its upper part. The face is behind the box's own top in the shadow map; testing it would
    // darken (and, at grazing depths, hatch) it. With thesis 6.2's rule it renders exactly as
    // without shadows: N.L alone shades it.
    Scene scene = planeBoxScene({0.0, -1.0, -0.3});
    Primitive& box = scene.meshes[1].primitives[0];
    for (std::size_t i = 0; i < box.positions.size(); ++i)
        box.normals[i] = glm::normalize(box.positions[i] - glm::vec3(0.0f, 1.0f, 0.0f));
    Settings s = lookAt({0.0, 3.0, -7.0}, {0.0, 1.0, -1.0});
    s.display.toneMapping = ToneMapping::None;
    s.display.hemisphereAmbient = false;
    s.bias.mode = DepthOffset::None;
    s.filter.filter = ShadowFilter::Nearest;
    const RgbaImage shadowed = render(scene, s);
    s.shadows = false;
    const RgbaImage unshadowed = render(scene, s);
    int compared = 0, directlyLit = 0;
    const glm::u8vec4 ambientOnly = unshadowed.at(project(s, kWidth, kHeight, {0.0, 0.15, -1.0}).x,
                                                  project(s, kWidth, kHeight, {0.0, 0.15, -1.0}).y);
    for (double y = 0.2; y <= 1.8; y += 0.1)
        for (double x = -0.8; x <= 0.8; x += 0.1) {
            const glm::ivec2 p = project(s, kWidth, kHeight, {x, y, -1.0});
            const glm::u8vec4 a = shadowed.at(p.x, p.y), b = unshadowed.at(p.x, p.y);
            EXPECT_NEAR(int(a.r), int(b.r), 2) << "back face at x " << x << " y " << y;
            directlyLit += b.r > ambientOnly.r + 10;
            ++compared;
        }
    // The face does get direct light through its tilted normals (else the comparison says nothing).
    EXPECT_GT(directlyLit, compared / 8);
    // And the shadow map does hold the face in shadow: the shadow term alone shows it dark there.
    s.shadows = true;
    s.viewMode = ViewMode::ShadowTermOnly;
    const RgbaImage term = render(scene, s);
    const glm::ivec2 upper = project(s, kWidth, kHeight, {0.0, 1.7, -1.0});
    EXPECT_LT(int(term.at(upper.x, upper.y).r), 150);
}

TEST_F(DisplayRender, MsaaSmoothsSilhouettesAndChangesNothingElse) {
    // The red box against the grey ground: with 4x MSAA its silhouette pixels take in-between
    // colours; the flat interiors stay as they were.
    const Scene scene = planeBoxScene();
    Settings s = lookAt({3.0, 4.0, 9.0}, {0.0, 1.0, 0.0});
    s.shadows = false;
    const RgbaImage aliased = render(scene, s);
    s.display.msaaSamples = 4;
    const RgbaImage smooth = render(scene, s);
    int changed = 0, interiorChanged = 0;
    const glm::ivec2 inside = project(s, kWidth, kHeight, {0.0, 1.0, 1.0});
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const bool differs = std::abs(int(aliased.at(x, y).r) - int(smooth.at(x, y).r)) > 8;
            changed += differs;
            if (std::abs(x - inside.x) < 6 && std::abs(y - inside.y) < 6) interiorChanged += differs;
        }
    EXPECT_GT(changed, 40);  // the silhouette edges
    EXPECT_LT(changed, kWidth * kHeight / 20);
    EXPECT_EQ(interiorChanged, 0);
}

TEST_F(DisplayRender, GroundPlaneReceivesTheShadowOfAFloatingModelAndComesOffAgain) {
    // A box 1 m up with nothing under it: around it the camera sees sky. With the ground plane
    // (just below its lowest point) there is lit ground, and the box's shadow on it.
    Scene scene;
    scene.materials.push_back({"Box", {0.8f, 0.1f, 0.1f, 1.0f}});
    scene.meshes.push_back({"Box", {boxPrimitive({-1, 1, -1}, {1, 3, 1}, 0)}});
    addInstance(scene, 0, glm::dmat4(1.0));
    Light sun;
    sun.direction = glm::normalize(glm::dvec3(0.0, -1.0, 0.5));  // the shadow falls in front: z in [1, 2]
    scene.lights.push_back(sun);
    const Scene original = scene;
    Settings s = lookAt({0.0, 6.0, 9.0}, {0.0, 0.5, 0.0});
    const glm::ivec2 away = project(s, kWidth, kHeight, {2.4, 1.0, 1.8});
    const RgbaImage floating = render(scene, s);
    Scene withGround = scene;  // another object: the test renderer re-uploads by identity
    const GroundPlaneUndo undo = addGroundPlane(withGround);
    const RgbaImage grounded = render(withGround, s);
    EXPECT_EQ(withGround.instances.size(), original.instances.size() + 1);
    EXPECT_LT(withGround.bounds.min.y, 1.0);
    // Away from the box: sky without the plane, lit grey ground with it.
    EXPECT_GT(floating.at(away.x, away.y).b, floating.at(away.x, away.y).r + 30);
    EXPECT_NEAR(int(grounded.at(away.x, away.y).r), int(grounded.at(away.x, away.y).b), 6);
    const glm::ivec2 shade = project(s, kWidth, kHeight, {0.0, 1.0, 1.5});
    EXPECT_LT(luminance(grounded.at(shade.x, shade.y)) + 40, luminance(grounded.at(away.x, away.y)));
    removeGroundPlane(withGround, undo);
    EXPECT_EQ(withGround.instances.size(), original.instances.size());
    EXPECT_EQ(withGround.meshes.size(), original.meshes.size());
    EXPECT_EQ(withGround.bounds, original.bounds);
}

}  // namespace
}  // namespace shadowlab::test
