#pragma once
// The scene's geometry, instances, materials and textures on the GPU, uploaded once per scene.
// Instance matrices and materials live in storage buffers (shaders/scene_vertex.glsl,
// material.glsl) indexed by Scene order; an instanced vertex attribute carries the instance index.
// It comes from one of two lists: the fixed slot order (instances grouped by mesh, so a run of
// consecutive slots is one instanced call), or a pass's culled draw list, grouped by mesh and
// winding so each primitive is one instanced call per pass (skip.groupedDraws).
#include "culling/instance_culling.h"
#include "culling/mesh_clusters.h"
#include "gl/gl_objects.h"
#include "scenes/load_timings.h"
#include "scenes/scene.h"
#include "resources/gpu_deform.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace shadowlab {

struct GpuPrimitive {
    GLint baseVertex = 0;
    GLuint firstIndex = 0;
    GLsizei indexCount = 0;
    int material = -1;
    int clusters = -1;  // index into GpuScene::clusters(), -1 when always drawn whole
};

struct GpuMesh {
    std::vector<GpuPrimitive> primitives;
    std::vector<int> instances;  // indices into Scene::instances, in the order of their GPU slots
    GLuint firstSlot = 0;        // slot of instances[0] in the instance buffer
    bool clustered = false;      // every primitive has clusters (mesh_clusters.h)
};

// Which instances a pass draws (culling result), one flag per Scene::instances entry.
using InstanceMask = std::vector<std::uint8_t>;

// What a draw needs to know about its material: the storage-buffer entry, the texture to bind and
// which shader variant applies.
struct GpuMaterial {
    int slot = 0;  // entry in the material buffer (the default material is the last one)
    GLuint texture = 0, sampler = 0;
    bool textured = false;
    bool alphaTest = false;  // glTF MASK
    bool blended = false;    // glTF BLEND
    bool doubleSided = false;
};

// One instanced draw of every primitive of `mesh` over `count` entries of the uploaded draw list.
struct DrawGroup {
    int mesh = 0;
    bool mirrored = false;
    GLuint first = 0;
    GLsizei count = 0;
};

class GpuScene {
public:
    // `deferTextures`: images start as 1x1 white (the material's factor shows) and are uploaded by
    // uploadPendingTextures, a few per frame, so opening Sponza does not freeze the window for the
    // whole upload (294 ms on llvmpipe, of which the textures are most).
    // `timings` (optional) gets the cluster split and the upload (the rest) added.
    explicit GpuScene(const Scene& scene, bool deferTextures = false, LoadTimings* timings = nullptr);

    // Uploads deferred textures (pixels and mipmaps) until `budgetMs` has passed, at least one;
    // `scene` must be the one constructed from, its pixels unchanged. True when one was uploaded.
    bool uploadPendingTextures(const Scene& scene, double budgetMs);
    std::size_t pendingTextures() const { return pendingTextures_.size(); }

    // Re-uploads the instance matrices after the node transforms changed (animation), and the
    // vertices of deformed meshes (skins, morph targets) whose pose changed. `changed` (optional)
    // gets the instances whose world matrix or pose differs from the previous upload.
    void updateInstances(const Scene& scene, std::vector<std::uint32_t>* changed = nullptr);
    // Vertices deformed on the GPU since the upload (skins, morph targets).
    std::size_t deformedVertices() const { return deformer_ ? deformer_->deformedVertices() : 0; }
    GLuint vertexBuffer() const { return vertices_.id(); }  // position, normal, texcoord (8 floats)

    // Binds the vertex array (slot order) and the instance and material buffers.
    void bindVertexArray() const;
    const GpuMaterial& material(int index) const {
        return index >= 0 && index + 1 < int(materials_.size()) ? materials_[std::size_t(index)] : materials_.back();
    }
    // Uploads the culled instances as a draw list grouped by mesh and winding (ascending instance
    // order inside a group) and points the instance attribute at it; restoreSlotOrder() undoes that.
    std::vector<DrawGroup> bindDrawList(const Scene& scene, const InstanceList& instances);
    void restoreSlotOrder() const;
    const std::vector<GpuMesh>& meshes() const { return meshes_; }
    // Clusters of the large primitives, index ranges absolute in the index buffer.
    const std::vector<ClusteredPrimitive>& clusters() const { return clusters_; }
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
    // Keeps `clustered` (index ranges relative to the primitive) with absolute ranges.
    void addClusters(GpuPrimitive& primitive, ClusteredPrimitive clustered);
    // Fills materials_ (texture ids included) and the material buffer. Whatever replaces a texture
    // later (streamed decoding) must call it again, and the renderer must count it as a scene
    // change: alpha-masked textures shape the shadow map (ShadowMapKey::sceneVersion).
    void uploadMaterials(const Scene& scene);
    // The texture of `t` with its pixels and mipmaps (1x1 white for an unusable image).
    static gl::Texture uploadTexture(const Texture& t);
    std::vector<std::size_t> pendingTextures_;  // Scene::textures indices still 1x1 white

    gl::VertexArray vao_;
    gl::Buffer vertices_;
    gl::Buffer indices_;
    gl::Buffer instanceData_;   // storage buffer, Scene::instances order
    gl::Buffer slotInstances_;  // slot -> instance index (the fixed, mesh-grouped order)
    gl::Buffer drawList_;       // a pass's culled instance indices, re-specified per pass
    gl::Buffer materialData_;   // storage buffer of MaterialData (material.glsl)
    std::vector<GpuMaterial> materials_;
    std::vector<GLuint> groupCounts_;  // scratch for bindDrawList
    std::vector<gl::Texture> textures_;
    std::vector<gl::SamplerObject> samplers_;
    std::vector<GpuMesh> meshes_;
    std::vector<ClusteredPrimitive> clusters_;
    std::size_t triangles_ = 0;
    std::vector<glm::dmat4> uploadedWorld_;  // per Scene::instances entry, as last uploaded
    std::unique_ptr<GpuDeformer> deformer_;  // skinned and morphed meshes (none: null)
    std::vector<std::uint8_t> movedScratch_;
};

}  // namespace shadowlab
