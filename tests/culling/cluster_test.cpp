// Clusters of large meshes: the build keeps every triangle once, in contiguous, compact, bounded
// runs; the cull volume agrees with the instance tests (boxMayBeVisible, casterCanReach); and the
// clusters kept for an instance hold every triangle that reaches into the volume.
#include "culling/instance_culling.h"
#include "culling/mesh_clusters.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace shadowlab {
namespace {

// A height-field terrain of n x n quads over [0, size]^2 in x, z.
struct Terrain {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
};

Terrain terrain(std::uint32_t n, float size) {
    Terrain t;
    for (std::uint32_t z = 0; z <= n; ++z)
        for (std::uint32_t x = 0; x <= n; ++x) {
            const float fx = size * float(x) / float(n), fz = size * float(z) / float(n);
            t.positions.push_back({fx, 2.0f * std::sin(fx * 0.3f) * std::cos(fz * 0.2f), fz});
        }
    for (std::uint32_t z = 0; z < n; ++z)
        for (std::uint32_t x = 0; x < n; ++x) {
            const std::uint32_t a = z * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
            for (std::uint32_t i : {a, c, b, b, c, d}) t.indices.push_back(i);
        }
    return t;
}

using Triangle = std::array<std::uint32_t, 3>;
std::vector<Triangle> sortedTriangles(const std::uint32_t* indices, std::size_t count) {
    std::vector<Triangle> out;
    for (std::size_t k = 0; k + 2 < count; k += 3) out.push_back({indices[k], indices[k + 1], indices[k + 2]});
    std::sort(out.begin(), out.end());
    return out;
}

TEST(MeshClusters, EveryTriangleOnceInContiguousBoundedCompactClusters) {
    const Terrain t = terrain(100, 100.0f);  // 20,000 triangles
    std::vector<std::uint32_t> out{7, 7, 7};  // appended after what is there
    const ClusteredPrimitive c = clusterTriangles(t.positions, t.indices, out);
    ASSERT_EQ(out.size(), 3 + t.indices.size());
    EXPECT_EQ(sortedTriangles(out.data() + 3, t.indices.size()), sortedTriangles(t.indices.data(), t.indices.size()));
    ASSERT_EQ(c.clusters.size(), (20000 + kClusterTriangles - 1) / kClusterTriangles);
    std::uint32_t next = 0;
    double boxArea = 0.0;
    for (const MeshCluster& cluster : c.clusters) {
        EXPECT_EQ(cluster.firstIndex, next);
        EXPECT_EQ(cluster.indexCount % 3, 0u);
        EXPECT_LE(cluster.indexCount, 3 * kClusterTriangles);
        next += cluster.indexCount;
        for (std::uint32_t k = 0; k < cluster.indexCount; ++k) {
            const glm::dvec3 p(t.positions[out[3 + cluster.firstIndex + k]]);
            EXPECT_TRUE(glm::all(glm::lessThanEqual(cluster.bounds.min, p)) &&
                        glm::all(glm::lessThanEqual(p, cluster.bounds.max)));
        }
        boxArea += cluster.bounds.extent().x * cluster.bounds.extent().z;
    }
    EXPECT_EQ(next, t.indices.size());
    // Spatially compact: the clusters' boxes overlap little. The terrain's area is 100 x 100; the
    // median split's boxes cover 1.16x that, runs of the input's row order 1.74x, runs of a Morton
    // order 2.9x.
    EXPECT_LT(boxArea, 1.3 * 100.0 * 100.0);
    EXPECT_EQ(c.hierarchy.instanceCount(), c.clusters.size());
}

TEST(MeshClusters, SmallOrMalformedPrimitivesAreAppendedUnchangedAndNotClustered) {
    const Terrain small = terrain(10, 10.0f);  // 200 triangles, under the threshold
    std::vector<std::uint32_t> out;
    EXPECT_TRUE(clusterTriangles(small.positions, small.indices, out).empty());
    EXPECT_EQ(out, small.indices);

    Terrain bad = terrain(100, 100.0f);
    bad.indices[10] = std::uint32_t(bad.positions.size());  // names no position
    out.clear();
    EXPECT_TRUE(clusterTriangles(bad.positions, bad.indices, out).empty());
    EXPECT_EQ(out, bad.indices);

    Terrain nan = terrain(100, 100.0f);
    nan.positions[5].y = std::nanf("");
    out.clear();
    EXPECT_TRUE(clusterTriangles(nan.positions, nan.indices, out).empty());
    EXPECT_EQ(out, nan.indices);

    Terrain partial = terrain(100, 100.0f);
    partial.indices.pop_back();  // not whole triangles
    out.clear();
    EXPECT_TRUE(clusterTriangles(partial.positions, partial.indices, out).empty());
    EXPECT_EQ(out, partial.indices);

    out.clear();
    EXPECT_TRUE(clusterTriangles({}, {}, out).empty());
    EXPECT_TRUE(out.empty());
    EXPECT_TRUE(singleCluster({}, {}).empty());
    EXPECT_TRUE(singleCluster(partial.positions, partial.indices).empty());
    const ClusteredPrimitive one = singleCluster(small.positions, small.indices);
    ASSERT_EQ(one.clusters.size(), 1u);
    EXPECT_EQ(one.clusters[0].indexCount, small.indices.size());
}

TEST(MeshClusters, FlatAndDegeneratePositionsStillClusterEveryTriangle) {
    Terrain t = terrain(64, 64.0f);
    for (glm::vec3& p : t.positions) p = glm::vec3(1.0f);  // every triangle collapsed onto one point
    std::vector<std::uint32_t> out;
    const ClusteredPrimitive c = clusterTriangles(t.positions, t.indices, out);
    EXPECT_EQ(sortedTriangles(out.data(), out.size()), sortedTriangles(t.indices.data(), t.indices.size()));
    EXPECT_FALSE(c.empty());
}

Aabb randomBox(std::mt19937& rng, double spread) {
    std::uniform_real_distribution<double> pos(-spread, spread), size(0.01, 5.0);
    const glm::dvec3 c{pos(rng), pos(rng) * 0.2, pos(rng)}, h{size(rng), size(rng), size(rng)};
    return {c - h, c + h};
}

ClipPlanes viewPlanes(glm::dvec3 eye, double yaw, double pitch) {
    Settings s;
    s.camera.position = eye;
    s.camera.yawDeg = yaw;
    s.camera.pitchDeg = pitch;
    s.camera.farPlane = 60.0;
    const ViewFrustum v = viewFrustum(s.camera, 16.0 / 9.0);
    return clipPlanes(v.projectionMatrix() * v.viewMatrix());
}

TEST(CullVolume, AgreesWithTheInstanceTestsOnRandomBoxes) {
    std::mt19937 rng(3);
    Scene scene;
    scene.bounds = {{-100, -20, -100}, {100, 20, 100}};
    int kept = 0, culled = 0;
    for (int k = 0; k < 20; ++k) {
        const ClipPlanes planes = viewPlanes({k * 3.0 - 30.0, 5.0, 10.0 - k}, k * 17.0, -10.0);
        const CullVolume frustum = CullVolume::viewFrustum(planes);
        Settings s;
        s.camera.position = {k * 3.0 - 30.0, 5.0, 10.0 - k};
        s.camera.yawDeg = k * 17.0;
        s.light.source = LightSource::Sun;
        s.light.azimuthDeg = k * 31.0;
        s.light.elevationDeg = 20.0 + k * 3.0;
        const ViewFrustum view = viewFrustum(s.camera, 16.0 / 9.0);
        const ShadowSetup setup = computeShadowSetup(view, shadowLight(resolveLight(scene, s.light, 0.0)),
                                                     scene.bounds, shadowParams(s, view, scene.bounds));
        ASSERT_TRUE(setup.valid);
        const CullVolume casters = CullVolume::casterReach(setup);
        for (int b = 0; b < 500; ++b) {
            const Aabb box = randomBox(rng, 100.0);
            EXPECT_EQ(frustum.mayContain(box), boxMayBeVisible(planes, box));
            EXPECT_EQ(casters.mayContain(box), casterCanReach(setup, box));
            (casters.mayContain(box) ? kept : culled)++;
        }
    }
    EXPECT_GT(kept, 100);
    EXPECT_GT(culled, 100);
    ShadowSetup invalid;
    EXPECT_FALSE(CullVolume::casterReach(invalid).mayContain(scene.bounds));
    EXPECT_TRUE(CullVolume().keepsEverything());
}

// Does the triangle (world space) reach into the volume's convex body? Sampled: its vertices,
// edge midpoints and centroid; a kept cluster must hold every triangle with such a point inside.
bool triangleSampleInside(const std::vector<glm::dvec4>& planes, const std::array<glm::dvec3, 3>& v) {
    const std::array<glm::dvec3, 7> samples{v[0], v[1], v[2], 0.5 * (v[0] + v[1]), 0.5 * (v[1] + v[2]),
                                            0.5 * (v[0] + v[2]), (v[0] + v[1] + v[2]) / 3.0};
    for (const glm::dvec3& p : samples) {
        bool inside = true;
        for (const glm::dvec4& plane : planes) inside = inside && glm::dot(glm::dvec3(plane), p) + plane.w > 1e-6;
        if (inside) return true;
    }
    return false;
}

TEST(MeshClusters, KeptClustersMatchTheLinearLoopAndHoldEveryTriangleInsideTheFrustum) {
    const Terrain t = terrain(120, 120.0f);
    std::vector<std::uint32_t> indices;
    const ClusteredPrimitive c = clusterTriangles(t.positions, t.indices, indices);
    // Instances moved, rotated, scaled and mirrored: the volume goes to object space per instance.
    const std::array<glm::dmat4, 3> worlds{
        glm::dmat4(1.0),
        glm::rotate(glm::translate(glm::dmat4(1.0), {-60.0, -1.0, -40.0}), 0.7, glm::dvec3(0, 1, 0)),
        glm::scale(glm::translate(glm::dmat4(1.0), {40.0, 0.0, -60.0}), glm::dvec3(-1.0, 1.5, 0.8))};
    int partial = 0;
    for (int k = 0; k < 12; ++k) {
        const ClipPlanes planes = viewPlanes({10.0 + 4.0 * k, 6.0, 20.0 + 3.0 * k}, k * 30.0, -15.0);
        const CullVolume volume = CullVolume::viewFrustum(planes);
        const std::vector<glm::dvec4> worldPlanes(std::begin(planes.planes), std::end(planes.planes));
        for (const glm::dmat4& world : worlds) {
            std::vector<std::uint32_t> kept;
            keptClusters(c, world, volume, kept);
            std::vector<std::uint32_t> linear;
            const CullVolume local = volume.inObjectSpace(world);
            for (std::uint32_t i = 0; i < c.clusters.size(); ++i)
                if (local.mayContain(c.clusters[i].bounds)) linear.push_back(i);
            EXPECT_EQ(kept, linear) << "view " << k;
            partial += !kept.empty() && kept.size() < c.clusters.size();
            std::vector<bool> isKept(c.clusters.size(), false);
            for (std::uint32_t i : kept) isKept[i] = true;
            for (std::uint32_t i = 0; i < c.clusters.size(); ++i) {
                if (isKept[i]) continue;
                const MeshCluster& cluster = c.clusters[i];
                for (std::uint32_t f = cluster.firstIndex; f < cluster.firstIndex + cluster.indexCount; f += 3) {
                    std::array<glm::dvec3, 3> v;
                    for (int j = 0; j < 3; ++j)
                        v[j] = glm::dvec3(world * glm::dvec4(glm::dvec3(t.positions[indices[f + j]]), 1.0));
                    ASSERT_FALSE(triangleSampleInside(worldPlanes, v)) << "culled cluster " << i << " view " << k;
                }
            }
        }
    }
    EXPECT_GT(partial, 12);  // the views do cull part of the terrain
}

}  // namespace
}  // namespace shadowlab
