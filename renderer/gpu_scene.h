#pragma once
// The scene's geometry, instances, materials and textures on the GPU, uploaded once per scene.
// Instances are grouped by mesh so every primitive is drawn with one instanced call per run of
// visible instances (baseInstance selects the instance matrices).
#include "gl/gl_objects.h"
#include "scenes/scene.h"

#include <cstdint>
#include <vector>

namespace shadowlab {

struct GpuPrimitive {
    GLint baseVertex = 0;
    GLuint firstIndex = 0;
    GLsizei indexCount = 0;
    int material = -1;
};

struct GpuMesh {
    std::vector<GpuPrimitive> primitives;
    std::vector<int> instances;  // indices into Scene::instances, in the order of their GPU slots
    GLuint firstSlot = 0;        // slot of instances[0] in the instance buffer
};

// Which instances a pass draws (culling result), one flag per Scene::instances entry.
using InstanceMask = std::vector<std::uint8_t>;

class GpuScene {
public:
    explicit GpuScene(const Scene& scene);

    // Re-uploads the instance matrices after the node transforms changed (animation).
    void updateInstances(const Scene& scene);

    void bindVertexArray() const { glBindVertexArray(vao_.id()); }
    const std::vector<GpuMesh>& meshes() const { return meshes_; }
    GLuint texture(int index) const { return index >= 0 && index < int(textures_.size()) ? textures_[index].id() : 0; }
    GLuint sampler(int index) const { return index >= 0 && index < int(samplers_.size()) ? samplers_[index].id() : 0; }
    std::size_t triangleCount() const { return triangles_; }

    // Calls draw(primitive, material, firstSlot, count, mirrored) for every run of consecutive
    // instances that `mask` keeps (all when the mask is empty) and that share a winding.
    template <class DrawRun>
    void forEachRun(const Scene& scene, const InstanceMask& mask, DrawRun&& draw) const {
        for (const GpuMesh& mesh : meshes_) {
            std::size_t i = 0;
            const std::size_t n = mesh.instances.size();
            while (i < n) {
                const int inst = mesh.instances[i];
                if (!mask.empty() && !mask[inst]) { ++i; continue; }
                const bool mirrored = scene.instances[inst].mirrored;
                std::size_t j = i + 1;
                while (j < n && (mask.empty() || mask[mesh.instances[j]]) && scene.instances[mesh.instances[j]].mirrored == mirrored) ++j;
                for (const GpuPrimitive& prim : mesh.primitives)
                    draw(prim, mesh.firstSlot + GLuint(i), GLsizei(j - i), mirrored);
                i = j;
            }
        }
    }

private:
    gl::VertexArray vao_;
    gl::Buffer vertices_;
    gl::Buffer indices_;
    gl::Buffer instanceData_;
    std::vector<gl::Texture> textures_;
    std::vector<gl::SamplerObject> samplers_;
    std::vector<GpuMesh> meshes_;
    std::size_t triangles_ = 0;
};

}  // namespace shadowlab
