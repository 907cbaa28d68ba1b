#pragma once
// A pass's draws of clustered meshes (culling/mesh_clusters.h): for every listed instance of such
// a mesh, the clusters that may matter under the list's cull volume become indirect draw commands
// (adjacent kept clusters merged into one), batched by material and winding, each batch one
// glMultiDrawElementsIndirect (GL 4.3). baseInstance is the instance's slot of the fixed slot
// order, so the draw reads its instance index as an instanced draw of that slot would.
#include "frame/frame_stats.h"
#include "gl/gl_objects.h"
#include "resources/gpu_scene.h"

#include <cstdint>
#include <vector>

namespace shadowlab {

// DrawElementsIndirectCommand (GL 4.6 core spec, 10.4).
struct IndirectCommand {
    GLuint count = 0;
    GLuint instanceCount = 1;
    GLuint firstIndex = 0;
    GLint baseVertex = 0;
    GLuint baseInstance = 0;
};

struct IndirectBatch {
    int material = -1;
    bool mirrored = false;
    std::size_t firstCommand = 0;  // into the indirect buffer
    GLsizei commands = 0;
    std::size_t triangles = 0;
    std::size_t clustersKept = 0;
    std::size_t clustersCulled = 0;
};

class ClusterDrawList {
public:
    // Splits `instances` into those of meshes drawn whole (`whole`, keeping the list's volume) and
    // those drawn by clusters: the clusters `volume` may contain become commands, uploaded and
    // bound to GL_DRAW_INDIRECT_BUFFER. Returns the batches (valid until the next call).
    const std::vector<IndirectBatch>& build(const Scene& scene, const GpuScene& gpu, const InstanceList& instances,
                                            const CullVolume& volume, InstanceList& whole);
    // Draws one batch (its state already set); the buffer bound by build() must still be bound.
    static void draw(const IndirectBatch& batch);

private:
    gl::Buffer buffer_;
    std::vector<IndirectCommand> commands_;
    std::vector<IndirectBatch> batches_;
    std::vector<std::vector<IndirectCommand>> perBatch_;  // scratch, one per (material, winding)
    std::vector<std::uint32_t> kept_;
};

// Adds a drawn batch to the pass's counts (one call, its triangles and clusters).
void countBatch(const IndirectBatch& batch, PassCounts& counts);

}  // namespace shadowlab
