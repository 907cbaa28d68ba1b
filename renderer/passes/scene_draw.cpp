// Drawing the scene's instances in a pass: grouped instanced draws over a culled list (or the
// runs of the fixed slot order), large meshes by their kept clusters through indirect draws
// (passes/cluster_draw_list.h), the material's program variant, storage-buffer entry, texture and
// face culling per draw. No per-draw uniform lookups by name and no per-draw string work.
#include "renderer.h"
#include "renderer_frame.h"

#include <algorithm>
#include <cstdint>

namespace shadowlab {

Renderer::ProgramFor Renderer::passPrograms(MaterialPrograms& programs, bool depthOnly, const Settings& settings,
                                            std::function<void(const gl::Program&)> setup) {
    // The pass's uniforms go onto each program the first time a draw of this pass uses it.
    auto prepared = std::make_shared<std::vector<const gl::Program*>>();
    const bool variants = settings.skip.shaderVariants;
    return [&programs, depthOnly, variants, prepared, setup = std::move(setup)](const GpuMaterial& material) {
        const DrawProgram p = programs.forMaterial(material, depthOnly, variants);
        if (std::find(prepared->begin(), prepared->end(), p.program) == prepared->end()) {
            setup(*p.program);
            prepared->push_back(p.program);
        }
        return p;
    };
}

void Renderer::drawScene(const gl::Program& program, const Frame& frame, const InstanceList& instances,
                         const CasterModel& sides, PassCounts& counts, Surfaces surfaces, bool targetMirrored) const {
    const DrawProgram only{&program, program.location("uMaterial")};
    drawScene([&](const GpuMaterial&) { return only; }, frame, instances, sides, counts, surfaces, targetMirrored);
}

void Renderer::drawScene(const ProgramFor& programFor, const Frame& frame, const InstanceList& instances,
                         const CasterModel& sides, PassCounts& counts, Surfaces surfaces, bool targetMirrored) const {
    if (instances.empty()) return;
    const Scene& scene = frame.scene;
    gpuScene_->bindVertexArray();
    const gl::Program* current = nullptr;
    GLuint boundTexture = ~0u;
    // The material's program, texture and face culling; false when this pass skips the material.
    auto useMaterial = [&](int material, bool mirrored) {
        const GpuMaterial& m = gpuScene_->material(material);
        if (surfaces != Surfaces::All && m.blended != (surfaces == Surfaces::Blended)) return false;
        const DrawProgram p = programFor(m);
        if (p.program != current) {
            p.program->use();
            current = p.program;
        }
        glUniform1i(p.materialLocation, m.slot);  // -1 (unused by this variant) is ignored by GL
        if (m.textured && m.texture != boundTexture) {
            glBindTextureUnit(0, m.texture);
            glBindSampler(0, m.sampler);
            boundTexture = m.texture;
        }
        // GL's front is the side facing the target (the light in the shadow pass, once the winding
        // below is set): `front` culls GL's back faces, `back` its front faces, `both` nothing.
        const CasterFaces faces = sides.faces(m.doubleSided);
        if (faces == CasterFaces::Both) {
            glDisable(GL_CULL_FACE);
        } else {
            glEnable(GL_CULL_FACE);
            glCullFace(faces == CasterFaces::Front ? GL_BACK : GL_FRONT);
        }
        // A negative-scale node flips the winding, and so does a mirroring target projection.
        glFrontFace(mirrored != targetMirrored ? GL_CW : GL_CCW);
        return true;
    };
    auto draw = [&](const GpuPrimitive& prim, GLuint first, GLsizei count, bool mirrored) {
        if (!useMaterial(prim.material, mirrored)) return;
        glDrawElementsInstancedBaseVertexBaseInstance(
            GL_TRIANGLES, prim.indexCount, GL_UNSIGNED_INT,
            reinterpret_cast<const void*>(std::uintptr_t(prim.firstIndex) * sizeof(std::uint32_t)), count,
            prim.baseVertex, first);
        ++counts.drawCalls;
        counts.triangles += std::size_t(prim.indexCount / 3) * std::size_t(count);
    };
    // Large meshes by their clusters kept under the list's volume, a few indirect calls; with
    // skip.clusterCulling off every cluster, in the same order, so only the culling differs.
    const InstanceList* whole = &instances;
    if (!gpuScene_->clusters().empty()) {
        static const CullVolume kEverything;
        const CullVolume& volume = frame.settings.skip.clusterCulling ? instances.volume : kEverything;
        for (const IndirectBatch& batch : clusterDraws_.build(scene, *gpuScene_, instances, volume, wholeScratch_))
            if (useMaterial(batch.material, batch.mirrored)) {
                ClusterDrawList::draw(batch);
                countBatch(batch, counts);
            }
        glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
        whole = &wholeScratch_;
    }
    if (frame.settings.skip.groupedDraws) {
        // One instanced call per primitive and (mesh, winding) group of the culled list.
        for (const DrawGroup& g : gpuScene_->bindDrawList(scene, *whole))
            for (const GpuPrimitive& prim : gpuScene_->meshes()[std::size_t(g.mesh)].primitives)
                draw(prim, g.first, g.count, g.mirrored);
        gpuScene_->restoreSlotOrder();
    } else if (!whole->empty()) {
        // One call per run of consecutive visible slots (the linear layout).
        InstanceMask mask(scene.instances.size(), 0);
        for (std::uint32_t i : *whole) mask[i] = 1;
        gpuScene_->forEachRun(scene, mask, draw);
    }
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    glDisable(GL_CULL_FACE);
}

}  // namespace shadowlab
