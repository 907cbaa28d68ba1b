#pragma once
// Large meshes as clusters: spatially compact runs of a few hundred triangles, each with its
// object-space bounds, so a pass skips the parts of a mesh it cannot see (view frustum) or that
// cannot shadow anything visible (B) - instance culling one level finer. GL-free.
//
// Triangles are split at the median of their centroids along the longest axis until a part fits
// trianglesPerCluster; each cluster is one contiguous range of the reordered index list, in the
// split's depth-first order, so neighbouring clusters in a view are often neighbours in the list
// too (one indirect command). A spatial split rather than meshoptimizer's meshlets: meshlets are
// grown for vertex reuse, culling wants small boxes.
#include "culling/cull_volume.h"
#include "culling/instance_bvh.h"

#include <cstdint>
#include <vector>

namespace shadowlab {

struct MeshCluster {
    std::uint32_t firstIndex = 0;  // into the primitive's reordered index list
    std::uint32_t indexCount = 0;
    Aabb bounds;                   // object space
};

struct ClusteredPrimitive {
    std::vector<MeshCluster> clusters;  // in index order, contiguous
    InstanceBvh hierarchy;              // over the clusters' bounds

    bool empty() const { return clusters.empty(); }
};

// At most 256 triangles: the forest's terrain at x16 keeps its visible triangles within 1.3x of x1 and its
// culling well under a millisecond (docs/large-worlds.md).
constexpr std::uint32_t kClusterTriangles = 256;
// Smaller primitives are drawn whole: a cluster list would cost more than it saves.
constexpr std::size_t kMinClusteredTriangles = 8 * kClusterTriangles;

// Appends the primitive's indices to `out`: in cluster order when it is large enough
// (kMinClusteredTriangles) and well formed (whole triangles, every index naming a finite position), else
// unchanged, and then the result is empty. Cluster index ranges are relative to the first index
// appended. Linear memory, O(n log n) time.
ClusteredPrimitive clusterTriangles(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices,
                                    std::vector<std::uint32_t>& out,
                                    std::uint32_t trianglesPerCluster = kClusterTriangles,
                                    std::size_t minTriangles = kMinClusteredTriangles);

// The whole primitive as one cluster (bounds over its triangles), for the small primitives of a
// clustered mesh; empty when it is not well formed or has no triangle.
ClusteredPrimitive singleCluster(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices);

// The clusters of an instance with world matrix `world` that may matter under `volume` (which the
// instance's own bounds passed), ascending.
void keptClusters(const ClusteredPrimitive& primitive, const glm::dmat4& world, const CullVolume& volume,
                  std::vector<std::uint32_t>& kept);

}  // namespace shadowlab
