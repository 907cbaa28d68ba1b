#include "passes/cluster_draw_list.h"

#include <algorithm>

namespace shadowlab {

const std::vector<IndirectBatch>& ClusterDrawList::build(const Scene& scene, const GpuScene& gpu,
                                                         const InstanceList& instances, const CullVolume& volume,
                                                         InstanceList& whole) {
    whole.clear();
    whole.volume = instances.volume;
    batches_.clear();
    for (auto& list : perBatch_) list.clear();
    const auto& meshes = gpu.meshes();
    for (std::uint32_t i : instances) {
        const MeshInstance& inst = scene.instances[i];
        if (inst.mesh < 0 || std::size_t(inst.mesh) >= meshes.size() || !meshes[std::size_t(inst.mesh)].clustered) {
            whole.push_back(i);
            continue;
        }
        const GpuMesh& mesh = meshes[std::size_t(inst.mesh)];
        const auto at = std::lower_bound(mesh.instances.begin(), mesh.instances.end(), int(i));
        if (at == mesh.instances.end() || *at != int(i)) continue;
        const GLuint slot = mesh.firstSlot + GLuint(at - mesh.instances.begin());
        for (const GpuPrimitive& prim : mesh.primitives) {
            const ClusteredPrimitive& clustered = gpu.clusters()[std::size_t(prim.clusters)];
            keptClusters(clustered, inst.world, volume, kept_);
            // One batch per (material, winding): find or open it.
            auto batch = std::find_if(batches_.begin(), batches_.end(), [&](const IndirectBatch& b) {
                return b.material == prim.material && b.mirrored == inst.mirrored;
            });
            if (batch == batches_.end()) {
                batches_.push_back({prim.material, inst.mirrored});
                batch = batches_.end() - 1;
                if (perBatch_.size() < batches_.size()) perBatch_.resize(batches_.size());
            }
            std::vector<IndirectCommand>& list = perBatch_[std::size_t(batch - batches_.begin())];
            batch->clustersKept += kept_.size();
            batch->clustersCulled += clustered.clusters.size() - kept_.size();
            std::uint32_t previous = ~0u;
            for (std::uint32_t c : kept_) {
                const MeshCluster& cluster = clustered.clusters[c];
                batch->triangles += cluster.indexCount / 3;
                // Clusters are contiguous in the index buffer: a run of kept ones is one command.
                if (previous != ~0u && c == previous + 1) list.back().count += cluster.indexCount;
                else list.push_back({cluster.indexCount, 1, cluster.firstIndex, prim.baseVertex, slot});
                previous = c;
            }
        }
    }
    commands_.clear();
    for (std::size_t b = 0; b < batches_.size(); ++b) {
        batches_[b].firstCommand = commands_.size();
        batches_[b].commands = GLsizei(perBatch_[b].size());
        commands_.insert(commands_.end(), perBatch_[b].begin(), perBatch_[b].end());
    }
    if (!commands_.empty()) {
        if (!buffer_) buffer_ = gl::createBuffer();
        // Re-specified storage per pass: draws already issued keep reading the previous commands.
        glNamedBufferData(buffer_.id(), GLsizeiptr(commands_.size() * sizeof(IndirectCommand)), commands_.data(),
                          GL_STREAM_DRAW);
        glBindBuffer(GL_DRAW_INDIRECT_BUFFER, buffer_.id());
    }
    return batches_;
}

void ClusterDrawList::draw(const IndirectBatch& batch) {
    if (batch.commands == 0) return;
    glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT,
                                reinterpret_cast<const void*>(batch.firstCommand * sizeof(IndirectCommand)),
                                batch.commands, 0);
}

void countBatch(const IndirectBatch& batch, PassCounts& counts) {
    counts.drawCalls += batch.commands > 0 ? 1 : 0;
    counts.triangles += batch.triangles;
    counts.clustersVisible += batch.clustersKept;
    counts.clustersCulled += batch.clustersCulled;
}

}  // namespace shadowlab
