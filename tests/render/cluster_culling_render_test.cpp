// Cluster culling changes the work, never the picture: a merged world (terrain, a field of boxes
// and a small part in ONE mesh, drawn twice, once mirrored) rendered with skip.clusterCulling on
// and off must match within llvmpipe's rasterisation tolerance, while the passes cull clusters.
// A visible cluster culled by mistake leaves a hole of hundreds of pixels; the tolerance allows
// a few dozen pixels off by a few levels (different draw order at depth ties).
#include "render_helpers.h"
#include "test_scenes.h"

#include <cmath>

namespace shadowlab::test {
namespace {

// A rolling height field of n x n quads over [-size/2, size/2]^2 with smooth normals.
Primitive terrainPrimitive(int n, float size, int material) {
    Primitive p;
    p.material = material;
    auto height = [](float x, float z) { return 1.5f * std::sin(x * 0.15f) * std::cos(z * 0.11f); };
    for (int z = 0; z <= n; ++z)
        for (int x = 0; x <= n; ++x) {
            const float fx = size * (float(x) / float(n) - 0.5f), fz = size * (float(z) / float(n) - 0.5f);
            p.positions.push_back({fx, height(fx, fz), fz});
            const float e = 0.01f;
            p.normals.push_back(glm::normalize(glm::vec3(height(fx - e, fz) - height(fx + e, fz), 2.0f * e,
                                                         height(fx, fz - e) - height(fx, fz + e))));
        }
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) {
            const auto a = std::uint32_t(z * (n + 1) + x), b = a + 1, c = a + std::uint32_t(n) + 1, d = c + 1;
            for (std::uint32_t i : {a, c, b, b, c, d}) p.indices.push_back(i);
        }
    for (const glm::vec3& v : p.positions) p.bounds.extend(glm::dvec3(v));
    return p;
}

// Boxes on a grid, merged into one primitive (a merged export's props).
Primitive boxField(int perSide, float spacing, int material) {
    Primitive field;
    field.material = material;
    for (int i = 0; i < perSide; ++i)
        for (int j = 0; j < perSide; ++j) {
            const float x = spacing * (float(i) - 0.5f * float(perSide)), z = spacing * (float(j) - 0.5f * float(perSide));
            const float h = 1.0f + float((i * 7 + j * 3) % 5);
            const Primitive box = boxPrimitive({x - 0.4f, -1.8f, z - 0.4f}, {x + 0.4f, h, z + 0.4f}, material);
            const auto base = std::uint32_t(field.positions.size());
            field.positions.insert(field.positions.end(), box.positions.begin(), box.positions.end());
            field.normals.insert(field.normals.end(), box.normals.begin(), box.normals.end());
            for (std::uint32_t index : box.indices) field.indices.push_back(base + index);
            field.bounds.extend(box.bounds);
        }
    return field;
}

Scene mergedWorld() {
    Scene s;
    s.materials.push_back({"Ground", {0.5f, 0.7f, 0.4f, 1.0f}});
    s.materials.push_back({"Boxes", {0.8f, 0.3f, 0.2f, 1.0f}});
    s.materials.push_back({"Marker", {0.2f, 0.3f, 0.9f, 1.0f}});
    // 80,000 + 9,408 triangles in one mesh, and a 12-triangle part drawn as one cluster.
    s.meshes.push_back({"World",
                        {terrainPrimitive(200, 100.0f, 0), boxField(28, 3.5f, 1),
                         boxPrimitive({2.0f, 0.0f, 2.0f}, {3.0f, 4.0f, 3.0f}, 2)}});
    addInstance(s, 0, glm::dmat4(1.0));
    // The same world again, mirrored and moved (negative scale: the other winding).
    addInstance(s, 0, glm::scale(glm::translate(glm::dmat4(1.0), {100.0, 0.0, 0.0}), glm::dvec3(-1.0, 1.0, 1.0)));
    Light sun;
    sun.direction = glm::normalize(glm::dvec3(-0.6, -0.5, -0.3));
    s.lights.push_back(sun);
    return s;
}

class ClusterCullingRender : public RenderTest {
protected:
    // Pixels differing by more than `levels` in any channel.
    static int pixelsOff(const RgbaImage& a, const RgbaImage& b, int levels) {
        int off = 0;
        for (std::size_t i = 0; i + 3 < a.pixels.size() && i + 3 < b.pixels.size(); i += 4) {
            bool differs = false;
            for (int c = 0; c < 3; ++c) differs = differs || std::abs(int(a.pixels[i + c]) - int(b.pixels[i + c])) > levels;
            off += differs ? 1 : 0;
        }
        return off;
    }
};

TEST_F(ClusterCullingRender, MergedWorldLooksTheSameWithClusterCullingOnAndOff) {
    const Scene world = mergedWorld();
    const struct {
        glm::dvec3 eye, target;
        ShadowMethod method;
        bool cascades;
    } views[] = {{{-20.0, 4.0, 10.0}, {10.0, 0.0, -5.0}, ShadowMethod::Lispsm, false},
                 {{45.0, 6.0, 30.0}, {50.0, 0.0, -10.0}, ShadowMethod::SsmFocused, false},
                 {{-30.0, 3.0, -30.0}, {0.0, 1.0, 0.0}, ShadowMethod::Lispsm, true}};
    for (const auto& v : views) {
        Settings s = lookAt(v.eye, v.target);
        s.camera.farPlane = 60.0;
        s.method = v.method;
        s.csm.enabled = v.cascades;
        s.shadowMapSize = 1024;
        s.light.source = LightSource::Scene;
        s.skip.reuseShadowMap = false;  // each setting draws its own map
        FrameStats on, off;
        s.skip.clusterCulling = true;
        const RgbaImage culled = render(world, s, &on);
        s.skip.clusterCulling = false;
        const RgbaImage whole = render(world, s, &off);
        const int total = kWidth * kHeight;
        EXPECT_LE(pixelsOff(culled, whole, 3), total / 2000) << "view at " << v.eye.x << ", " << v.eye.z;
        // The passes did cull: fewer triangles, clusters left out, no more calls than drawn whole.
        EXPECT_GT(on.forwardPass.clustersCulled, 0u);
        EXPECT_GT(on.forwardPass.clustersVisible, 0u);
        EXPECT_GT(on.shadowPass.clustersCulled, 0u);
        EXPECT_LT(on.forwardPass.triangles, off.forwardPass.triangles / 2);
        EXPECT_LT(on.shadowPass.triangles, off.shadowPass.triangles);
        EXPECT_LE(on.forwardPass.drawCalls, off.forwardPass.drawCalls);
        EXPECT_EQ(off.forwardPass.clustersCulled, 0u);
        EXPECT_EQ(off.forwardPass.clustersVisible, on.forwardPass.clustersVisible + on.forwardPass.clustersCulled);
    }
}

}  // namespace
}  // namespace shadowlab::test
