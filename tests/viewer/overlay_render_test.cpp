// The overlay renderer through a headless EGL context (llvmpipe on CI): wireframes land where
// their clip coordinates say and only inside the inset, the depth inset maps near to dark and
// far to bright (also for reversed PSM maps), the scene inset draws the scene, and every call
// leaves the GL state as it found it.
#include "gl_test_context.h"
#include "overlays/overlay.h"
#include "resources/render_target.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <vector>

namespace shadowlab {
namespace {

constexpr int kSize = 128;

class OverlayRenderTest : public test::GlTest {
protected:
    void SetUp() override {
        test::GlTest::SetUp();
        std::string error;
        overlays = OverlayRenderer::create(error);
        ASSERT_TRUE(overlays) << error;
        target = std::make_unique<RenderTarget>(kSize, kSize);
        clearTarget();
    }
    void clearTarget() {
        glBindFramebuffer(GL_FRAMEBUFFER, target->framebuffer());
        const GLfloat black[4] = {0, 0, 0, 1};
        glClearBufferfv(GL_COLOR, 0, black);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    // Pixel at (x, y) with y counted from the BOTTOM (GL convention), as readColor() is top-first.
    glm::u8vec4 pixel(const RgbaImage& image, int x, int yFromBottom) const { return image.at(x, kSize - 1 - yFromBottom); }

    std::unique_ptr<OverlayRenderer> overlays;
    std::unique_ptr<RenderTarget> target;
};

TEST_F(OverlayRenderTest, WiresAreDrawnInTheirColourInsideTheInsetOnly) {
    // A horizontal segment through the middle of clip space, far wider than the inset.
    WireSet red;
    red.color = {1, 0, 0, 1};
    red.segments = {{-5.0, 0.0, 0.0}, {5.0, 0.0, 0.0}};
    const InsetRect rect{32, 32, 64, 64};
    overlays->drawWires(target->framebuffer(), rect, {red}, glm::dmat4(1.0));
    const RgbaImage image = target->readColor();
    // Along the inset's middle row (y = 32 + 32): red inside, black outside the inset.
    int redInside = 0;
    for (int x = 32; x < 96; ++x) redInside += pixel(image, x, 64).r > 200 || pixel(image, x, 65).r > 200;
    EXPECT_GT(redInside, 60);
    for (int x : {0, 10, 31, 96, 120}) EXPECT_EQ(pixel(image, x, 64).r, 0) << "x = " << x;
    // Away from the line, inside the inset: untouched.
    EXPECT_EQ(pixel(image, 64, 40).r, 0);
}

TEST_F(OverlayRenderTest, SegmentsBehindAProjectionCentreAreClippedNotWrapped) {
    // A perspective matrix: a segment from in front of the eye to behind it must not draw the
    // mirrored part (what a CPU divide by w would do).
    const glm::dmat4 proj = glm::perspective(glm::radians(90.0), 1.0, 0.1, 100.0);
    WireSet w;
    w.color = {0, 1, 0, 1};
    w.segments = {{0.5, 0.0, -1.0}, {0.5, 0.0, 1.0}};  // x = 0.5 from z = -1 (in front) to z = +1 (behind)
    overlays->drawWires(target->framebuffer(), {0, 0, kSize, kSize}, {w}, proj);
    const RgbaImage image = target->readColor();
    int greenLeft = 0, greenRight = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) (x < kSize / 2 ? greenLeft : greenRight) += pixel(image, x, y).g > 200;
    EXPECT_GT(greenRight, 0);   // the visible part lies right of the centre (x > 0 in front)
    EXPECT_EQ(greenLeft, 0);    // nothing mirrored to the left
}

TEST_F(OverlayRenderTest, DepthInsetMapsNearToDarkAndMarksEmptyTexels) {
    // A 64^2 depth texture: a ramp 0.2 .. 0.6 from left to right, the right quarter never written (1.0).
    gl::Texture depth = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(depth.id(), 1, GL_DEPTH_COMPONENT32F, 64, 64);
    std::vector<float> values(64 * 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) values[std::size_t(y * 64 + x)] = x < 48 ? 0.2f + 0.4f * float(x) / 47.0f : 1.0f;
    glTextureSubImage2D(depth.id(), 0, 0, 0, 64, 64, GL_DEPTH_COMPONENT, GL_FLOAT, values.data());
    // Compare mode on the texture itself must not matter: the inset binds its own sampler.
    glTextureParameteri(depth.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);

    overlays->drawDepthInset(target->framebuffer(), {0, 0, kSize, kSize}, depth.id(), false);
    RgbaImage image = target->readColor();
    const glm::u8vec4 nearPx = pixel(image, 4, 64), midPx = pixel(image, 48, 64), farPx = pixel(image, 90, 64),
                      empty = pixel(image, 120, 64);
    EXPECT_LT(nearPx.r, midPx.r);
    EXPECT_LT(midPx.r, farPx.r);
    EXPECT_GT(empty.b, empty.r + 20);  // dark blue: nothing was drawn there

    // Reversed (PSM inverted light): stored 1 - d, cleared to 0; the picture reads the same way.
    for (float& v : values) v = v >= 1.0f ? 0.0f : 1.0f - v;
    glTextureSubImage2D(depth.id(), 0, 0, 0, 64, 64, GL_DEPTH_COMPONENT, GL_FLOAT, values.data());
    clearTarget();
    overlays->drawDepthInset(target->framebuffer(), {0, 0, kSize, kSize}, depth.id(), true);
    image = target->readColor();
    EXPECT_NEAR(pixel(image, 4, 64).r, nearPx.r, 2);
    EXPECT_NEAR(pixel(image, 90, 64).r, farPx.r, 2);
    EXPECT_GT(pixel(image, 120, 64).b, pixel(image, 120, 64).r + 20);
}

// Cascades: the layers of the depth array side by side, each fitted to its own range
// (layer 0 a ramp left to right, layer 1 the same ramp right to left, layer 2 empty), under a
// strip in its split's colour.
TEST_F(OverlayRenderTest, LayeredDepthInsetShowsEveryCascadeLayerSideBySide) {
    gl::Texture depth = gl::createTexture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(depth.id(), 1, GL_DEPTH_COMPONENT32F, 32, 32, 3);
    std::vector<float> values(32 * 32 * 3, 1.0f);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            values[std::size_t(y * 32 + x)] = 0.1f + 0.5f * float(x) / 31.0f;                // layer 0
            values[std::size_t(32 * 32 + y * 32 + x)] = 0.1f + 0.5f * float(31 - x) / 31.0f;  // layer 1
        }
    glTextureSubImage3D(depth.id(), 0, 0, 0, 0, 32, 32, 3, GL_DEPTH_COMPONENT, GL_FLOAT, values.data());
    const std::vector<InsetRect> squares =
        overlays->drawDepthLayersInset(target->framebuffer(), {0, 0, kSize, 40}, depth.id(), 3);
    ASSERT_EQ(squares.size(), 3u);
    for (const InsetRect& q : squares) {
        EXPECT_EQ(q.width, q.height);
        EXPECT_LE(q.x + q.width, kSize);
    }
    EXPECT_GT(squares[1].x, squares[0].x + squares[0].width - 1);
    const RgbaImage image = target->readColor();
    auto at = [&](const InsetRect& q, double u, double v) {
        return pixel(image, q.x + int(u * (q.width - 1)), q.y + int(v * (q.height - 1)));
    };
    EXPECT_LT(at(squares[0], 0.1, 0.4).r + 40, at(squares[0], 0.9, 0.4).r);  // near left, far right
    EXPECT_GT(at(squares[1], 0.1, 0.4).r, at(squares[1], 0.9, 0.4).r + 40);  // mirrored
    EXPECT_GT(at(squares[2], 0.5, 0.4).b, at(squares[2], 0.5, 0.4).r + 20);  // empty layer: dark blue
    for (int i = 0; i < 3; ++i) {
        const glm::vec4 c = cascadeColor(i);
        const glm::u8vec4 top = at(squares[std::size_t(i)], 0.5, 1.0);
        EXPECT_NEAR(top.r, c.r * 255.0f, 2.0f) << i;
        EXPECT_NEAR(top.g, c.g * 255.0f, 2.0f) << i;
        EXPECT_NEAR(top.b, c.b * 255.0f, 2.0f) << i;
    }
    EXPECT_TRUE(overlays->drawDepthLayersInset(target->framebuffer(), {0, 0, kSize, 40}, 0, 3).empty());
    EXPECT_TRUE(overlays->drawDepthLayersInset(target->framebuffer(), {0, 0, 4, 4}, depth.id(), 3).empty());
}

TEST_F(OverlayRenderTest, SceneInsetDrawsTheSceneThroughTheMatrix) {
    Scene scene = test::planeBoxScene();
    GpuScene gpu(scene);
    // Looking down on the red box from above: red in the middle, grey ground around it.
    const glm::dmat4 view = glm::lookAt(glm::dvec3(0, 20, 0.01), glm::dvec3(0), glm::dvec3(0, 1, 0));
    const glm::dmat4 proj = glm::perspective(glm::radians(40.0), 1.0, 1.0, 50.0);
    overlays->drawScene(target->framebuffer(), {0, 0, kSize, kSize}, scene, gpu, proj * view, {0, -1, 0}, false);
    const RgbaImage image = target->readColor();
    const glm::u8vec4 centre = pixel(image, 64, 64), ground = pixel(image, 64, 8);
    EXPECT_GT(centre.r, 150);
    EXPECT_LT(centre.g, 120);
    EXPECT_GT(ground.g, 150);  // grey ground, lit from above
}

TEST_F(OverlayRenderTest, EveryCallRestoresTheStateItFound) {
    Scene scene = test::planeBoxScene();
    GpuScene gpu(scene);
    gl::Texture depth = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(depth.id(), 1, GL_DEPTH_COMPONENT32F, 8, 8);
    // Some unusual state the caller might have.
    gl::VertexArray vao = gl::createVertexArray();
    glBindFramebuffer(GL_FRAMEBUFFER, target->framebuffer());
    glViewport(3, 4, 50, 60);
    glEnable(GL_SCISSOR_TEST);
    glScissor(1, 2, 30, 40);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GEQUAL);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBindVertexArray(vao.id());
    glActiveTexture(GL_TEXTURE3);

    WireSet w;
    w.segments = {{0, 0, 0}, {1, 1, 0}};
    const InsetRect rect{10, 10, 80, 80};
    overlays->drawFrame(target->framebuffer(), rect);
    overlays->drawDepthInset(target->framebuffer(), rect, depth.id(), false);
    overlays->drawScene(target->framebuffer(), rect, scene, gpu, glm::dmat4(1.0), {0, -1, 0}, true);
    overlays->drawWires(target->framebuffer(), rect, {w}, glm::dmat4(1.0));

    GLint v[4], s[4], i = 0;
    glGetIntegerv(GL_VIEWPORT, v);
    EXPECT_EQ(std::vector<GLint>(v, v + 4), (std::vector<GLint>{3, 4, 50, 60}));
    glGetIntegerv(GL_SCISSOR_BOX, s);
    EXPECT_EQ(std::vector<GLint>(s, s + 4), (std::vector<GLint>{1, 2, 30, 40}));
    EXPECT_TRUE(glIsEnabled(GL_SCISSOR_TEST));
    EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
    EXPECT_TRUE(glIsEnabled(GL_BLEND));
    EXPECT_FALSE(glIsEnabled(GL_DEPTH_CLAMP));
    EXPECT_FALSE(glIsEnabled(GL_FRAMEBUFFER_SRGB));
    glGetIntegerv(GL_DEPTH_FUNC, &i);
    EXPECT_EQ(i, GL_GEQUAL);
    GLboolean mask = GL_TRUE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &mask);
    EXPECT_EQ(mask, GL_FALSE);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &i);
    EXPECT_EQ(GLuint(i), vao.id());
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &i);
    EXPECT_EQ(GLuint(i), target->framebuffer());
    glGetIntegerv(GL_CURRENT_PROGRAM, &i);
    EXPECT_EQ(i, 0);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &i);
    EXPECT_EQ(i, GL_TEXTURE3);

    // Back to the defaults for the next test.
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(0);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace
}  // namespace shadowlab
