// Skinned casters on the GPU: the Fox (a skinned mesh, glTF sample) walks over a ground plane.
// Two times of its animation must differ where the fox and its shadow are, the ray-cast truth
// (CPU skinning) must agree with the skinned shadow map as well as it does for the rest pose, and
// the shadow map must be redrawn when the fox moves but reused when only a non-caster moves.
#include "frame/ground_plane.h"
#include "groundtruth/ray_scene.h"
#include "groundtruth/shadow_truth.h"
#include "render_helpers.h"
#include "resources/gpu_scene.h"
#include "scenes/animation.h"
#include "scenes/gltf_loader.h"
#include "scenes/skinning.h"
#include "test_scenes.h"

#include <filesystem>
#include <iostream>

namespace shadowlab::test {
namespace {

namespace fs = std::filesystem;

const fs::path kFox = fs::path(SHADOWLAB_SHARED_SCENES) / "Fox/glTF-Binary/Fox.glb";

class AnimatedShadow : public RenderTest {
protected:
    Scene scene;
    Settings settings;
    Aabb restBounds;  // the fox at the rest pose

    bool loadFox() {
        if (!fs::exists(kFox)) return false;
        LoadResult r = loadScene(kFox);
        EXPECT_TRUE(r.ok()) << r.error;
        if (!r.ok()) return false;
        scene = std::move(*r.scene);
        restBounds = scene.bounds;
        addGroundPlane(scene);
        // Seen from the front-left, a little above: the fox and the shadow the sun throws beside it.
        const glm::dvec3 c = restBounds.center();
        const double size = glm::length(restBounds.extent());
        settings = lookAt(c + glm::dvec3(-0.9, 0.7, 1.2) * size, c);
        settings.camera.nearPlane = 0.05 * size;
        settings.camera.farPlane = 10.0 * size;
        settings.method = ShadowMethod::Lispsm;
        settings.shadowMapSize = 1024;
        return true;
    }
    // Poses the fox at `t` and uploads what moved.
    void poseAt(double t) {
        ASSERT_TRUE(animateScene(scene, t));
        if (renderer_) renderer_->updateInstances(scene);
    }
    // E_total (false shadow + false light over the receivers) of the frame at the current pose.
    double totalError() {
        std::string error;
        RenderTarget target(kWidth, kHeight);
        MeasureFrame frame;
        renderer_->renderMeasured(scene, settings, 0.0, Viewport{target.framebuffer(), 0, 0, kWidth, kHeight}, frame);
        auto rays = RayScene::build(scene, error);
        EXPECT_TRUE(rays) << error;
        if (!rays) return 1.0;
        std::vector<RayReceiver> receivers;
        for (std::size_t i = 0; i < frame.pixelCount(); ++i)
            if (frame.receiver[i]) receivers.push_back({frame.position[i], frame.normal[i]});
        const auto lit = rays->visibleFromLight(receivers, shadowLight(resolveLight(scene, settings.light, 0.0)), frame.casters);
        ShadowStateFrame states{kWidth, kHeight, frame.receiver, frame.shadowTerm,
                                std::vector<std::uint8_t>(frame.pixelCount(), 0)};
        std::size_t dark = 0;
        for (std::size_t i = 0, k = 0; i < frame.pixelCount(); ++i)
            if (frame.receiver[i]) {
                states.truthLit[i] = lit[k++];
                dark += lit[k - 1] == 0;
            }
        EXPECT_GT(dark, 300u) << "the fox's shadow is in view";
        return compareWithTruth(states).eTotal;
    }
};

// Threshold: at 256 x 192 the fox covers ~4,000 pixels; between 0.4 s and 0.9 s of its
// animations its legs and head move by a large fraction of their length, so at least 150 pixels
// on the fox and 40 on the ground (its shadow) change by more than 24 grey levels. In the bind
// pose (skins ignored) the two images are the same.
TEST_F(AnimatedShadow, TheFoxAndItsShadowMoveWithTheAnimation) {
    if (!loadFox()) GTEST_SKIP() << "shared scenes missing";
    poseAt(0.4);
    const RgbaImage a = render(scene, settings);
    const Aabb boundsA = scene.instances[0].worldBounds;
    poseAt(0.9);
    const RgbaImage b = render(scene, settings);
    Aabb fox = scene.instances[0].worldBounds;
    fox.extend(boundsA);
    std::size_t onFox = 0, onGround = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t i = (std::size_t(y) * kWidth + x) * 4;
            const glm::u8vec4 ca(a.pixels[i], a.pixels[i + 1], a.pixels[i + 2], 255);
            const glm::u8vec4 cb(b.pixels[i], b.pixels[i + 1], b.pixels[i + 2], 255);
            if (std::abs(luminance(ca) - luminance(cb)) <= 24.0) continue;
            glm::dvec3 origin, dir;
            pixelRay(settings, kWidth, kHeight, x, kHeight - 1 - y, origin, dir);
            (rayHitsBox(origin, dir, fox.min, fox.max) ? onFox : onGround)++;
        }
    std::cout << "pixels changed between 0.4 s and 0.9 s: on the fox " << onFox << ", on the ground " << onGround
              << "\n";
    EXPECT_GT(onFox, 150u);
    EXPECT_GT(onGround, 40u) << "the shadow on the ground did not move";
}

// The truth deforms its triangles with the same skinning: the animated frame's E_total stays
// within 0.5 points of the rest pose's (a truth in the bind pose would disagree over the shadow).
TEST_F(AnimatedShadow, TheTruthAgreesWithTheSkinnedShadowMap) {
    if (!loadFox()) GTEST_SKIP() << "shared scenes missing";
    render(scene, settings);  // creates the renderer, uploads the rest pose
    const double rest = totalError();
    poseAt(0.9);
    const double animated = totalError();
    std::cout << "E_total: rest pose " << rest * 100.0 << "%, at 0.9 s " << animated * 100.0 << "%\n";
    EXPECT_NEAR(animated, rest, 0.005);
}

// The map-reuse key sees skinned casters: redrawn when the fox moves, reused when the pose is the
// same, reused when only a non-caster (a box far behind the camera, its shadow away from the
// view) turns.
TEST_F(AnimatedShadow, TheShadowMapIsRedrawnOnlyWhenACasterMoves) {
    if (!loadFox()) GTEST_SKIP() << "shared scenes missing";
    const glm::dvec3 away = settings.camera.position + (settings.camera.position - restBounds.center()) +
                            glm::dvec3(0.0, -0.3 * restBounds.extent().y, 0.0);
    const double edge = 0.05 * glm::length(restBounds.extent());
    const glm::vec3 half(float(0.5 * edge));
    scene.meshes.push_back({"far box", {boxPrimitive(-half, half, -1)}});
    Node box;
    box.mesh = int(scene.meshes.size()) - 1;
    box.translation = glm::vec3(away);
    scene.nodes.push_back(box);
    scene.roots.push_back(int(scene.nodes.size()) - 1);
    poseAt(0.4);
    FrameStats stats;
    render(scene, settings, &stats);
    render(scene, settings, &stats);
    EXPECT_TRUE(stats.shadowMapReused) << "nothing moved";
    poseAt(0.4);  // the same pose again: nothing to upload
    render(scene, settings, &stats);
    EXPECT_TRUE(stats.shadowMapReused) << "the same pose";

    // A half turn about its centre (w = 0, y = 1: an exact matrix): a new instance matrix, the
    // same bounds (B and the scene bounds stay as they were, so only the caster test decides).
    scene.nodes.back().rotation = glm::quat(0.0f, 0.0f, 1.0f, 0.0f);
    poseAt(0.4);
    render(scene, settings, &stats);
    ASSERT_LT(stats.castersDrawn, scene.instances.size()) << "the far box must not be a caster";
    EXPECT_TRUE(stats.shadowMapReused) << "only a non-caster moved";

    poseAt(0.9);
    render(scene, settings, &stats);
    EXPECT_FALSE(stats.shadowMapReused) << "the skinned fox moved";
}

// deform.comp against the CPU's deformPrimitive (what the truth traces): the posed vertices read
// back from the vertex buffer, for a skin (Fox, CesiumMan) and morph targets (AnimatedMorphCube),
// at the loaded pose and after a pose change (only the changed instances are dispatched again).
TEST_F(AnimatedShadow, TheGpuDeformsAsTheCpuDoes) {
    for (const char* file : {"Fox/glTF-Binary/Fox.glb", "CesiumMan/glTF-Binary/CesiumMan.glb",
                             "AnimatedMorphCube/glTF-Binary/AnimatedMorphCube.glb"}) {
        SCOPED_TRACE(file);
        const fs::path path = fs::path(SHADOWLAB_SHARED_SCENES) / file;
        if (!fs::exists(path)) GTEST_SKIP() << "shared scenes missing";
        LoadResult r = loadScene(path);
        ASSERT_TRUE(r.ok()) << r.error;
        Scene& s = *r.scene;
        animateScene(s, 0.3);
        GpuScene gpu(s);
        for (double t : {0.3, 0.8}) {
            animateScene(s, t);
            std::vector<std::uint32_t> changed;
            gpu.updateInstances(s, &changed);
            EXPECT_EQ(changed.empty(), t == 0.3) << "t = " << t;
            const double tolerance = 2e-5 * glm::length(s.bounds.extent());
            std::size_t compared = 0;
            for (const MeshInstance& instance : s.instances) {
                if (!isDeformed(s, instance)) continue;
                const Pose pose = instancePose(s, instance);
                const auto& primitives = s.meshes[std::size_t(instance.mesh)].primitives;
                for (std::size_t k = 0; k < primitives.size(); ++k) {
                    std::vector<glm::vec3> positions, normals;
                    deformPrimitive(primitives[k], pose, positions, &normals);
                    std::vector<float> gpuVertices(positions.size() * 8);
                    const GLint base = gpu.meshes()[std::size_t(instance.mesh)].primitives[k].baseVertex;
                    glGetNamedBufferSubData(gpu.vertexBuffer(), GLintptr(base) * 32, GLsizeiptr(gpuVertices.size() * 4),
                                            gpuVertices.data());
                    for (std::size_t v = 0; v < positions.size(); ++v, ++compared) {
                        const glm::vec3 p(gpuVertices[8 * v], gpuVertices[8 * v + 1], gpuVertices[8 * v + 2]);
                        const glm::vec3 n(gpuVertices[8 * v + 3], gpuVertices[8 * v + 4], gpuVertices[8 * v + 5]);
                        ASSERT_LT(glm::length(glm::dvec3(p - positions[v])), tolerance) << "vertex " << v;
                        ASSERT_GT(glm::dot(n, normals[v]), 0.999f) << "normal of vertex " << v;
                    }
                }
            }
            EXPECT_GT(compared, 0u);
        }
    }
}

}  // namespace
}  // namespace shadowlab::test
