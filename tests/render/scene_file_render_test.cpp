// Real glTF files from ../shared/scenes through loader and renderer, headless.
#include "render_helpers.h"
#include "scenes/gltf_loader.h"

namespace shadowlab::test {
namespace {

const std::string kScenes = SHADOWLAB_SHARED_SCENES;

class SceneFileRender : public RenderTest {
protected:
    Scene load(const std::string& relative) {
        LoadResult r = loadScene(kScenes + "/" + relative);
        EXPECT_TRUE(r.ok()) << r.error;
        return r.ok() ? std::move(*r.scene) : Scene{};
    }
    // The settings a scene opens with: its first camera (or the framing camera).
    Settings opening(const Scene& scene) {
        Settings s;
        if (!scene.cameras.empty()) s.camera = cameraFromScene(scene.cameras.front(), s.camera);
        return s;
    }
};

TEST_F(SceneFileRender, TexturedBoxShowsItsTextureInTheMiddleAndSkyAtTheCorner) {
    const Scene scene = load("BoxTextured/glTF-Binary/BoxTextured.glb");
    ASSERT_FALSE(scene.textures.empty());
    const Settings s = opening(scene);
    const RgbaImage image = render(scene, s);
    // The framing camera looks at the box centre: the middle pixel is box, not sky.
    const glm::u8vec4 middle = image.at(kWidth / 2, kHeight / 2);
    const glm::u8vec4 corner = image.at(1, 1);
    EXPECT_NE(glm::ivec4(middle), glm::ivec4(corner));
    EXPECT_NEAR(corner.b, 218, 3);  // sky: linear 0.7 encoded as sRGB
    // The Cesium logo texture is not flat colour: the box face shows several distinct colours.
    std::set<int> colours;
    for (int y = kHeight / 3; y < 2 * kHeight / 3; y += 4)
        for (int x = kWidth / 3; x < 2 * kWidth / 3; x += 4) {
            const glm::u8vec4 c = image.at(x, y);
            colours.insert((c.r / 32) * 64 + (c.g / 32) * 8 + c.b / 32);
        }
    EXPECT_GE(colours.size(), 3u);
}

// The viewer streams textures after the geometry (Renderer::setScene(scene, true)): until they
// arrive the materials show their factor over white, and once all are in the image is the one a
// whole upload gives.
TEST_F(SceneFileRender, StreamedTexturesEndInTheImageOfAWholeUpload) {
    const Scene scene = load("BoxTextured/glTF-Binary/BoxTextured.glb");
    ASSERT_EQ(scene.textures.size(), 1u);
    const Settings s = opening(scene);
    const RgbaImage whole = render(scene, s);
    renderer_->setScene(scene, true);
    const RgbaImage before = render(scene, s);  // same scene object: render() keeps this upload
    EXPECT_NE(before.pixels, whole.pixels);     // the box is untextured for now
    EXPECT_EQ(renderer_->streamTextures(0.0), 0u);  // one texture, at least one per call
    EXPECT_EQ(renderer_->streamTextures(0.0), 0u);  // nothing left: nothing happens
    EXPECT_EQ(render(scene, s).pixels, whole.pixels);
}

TEST_F(SceneFileRender, SameFileInThreeContainersRendersTheSame) {
    const Scene gltf = load("Box/glTF/Box.gltf");
    const Scene glb = load("Box/glTF-Binary/Box.glb");
    const Scene embedded = load("Box/glTF-Embedded/Box.gltf");
    const Settings s = opening(gltf);
    const RgbaImage a = render(gltf, s);
    renderer_.reset();
    const RgbaImage b = render(glb, s);
    renderer_.reset();
    const RgbaImage c = render(embedded, s);
    EXPECT_EQ(a.pixels, b.pixels);
    EXPECT_EQ(a.pixels, c.pixels);
}

TEST_F(SceneFileRender, DegenerateFlatSceneRendersWithShadowsOnWithoutErrors) {
    // Zero thickness bounds, no normals, no material: the degenerate path of loader, math and passes.
    const Scene scene = load("TriangleWithoutIndices/glTF/TriangleWithoutIndices.gltf");
    for (ShadowMethod m : {ShadowMethod::SsmFocused, ShadowMethod::SsmUnfocused, ShadowMethod::Psm, ShadowMethod::Lispsm}) {
        Settings s = opening(scene);
        s.method = m;
        const RgbaImage image = render(scene, s);
        EXPECT_EQ(image.width, kWidth);
    }
}

}  // namespace
}  // namespace shadowlab::test
