#pragma once
// Skinned and morphed meshes on the GPU (shaders/deform.comp): the bind-pose attributes, joints,
// weights and target displacements uploaded once per scene; per pose change the joint matrices
// (computed on the CPU from the node hierarchy, O(joints)) and morph weights are uploaded and one
// dispatch per primitive writes the posed vertices into the scene's vertex buffer. Deforming once
// per pose rather than in every vertex shader keeps all passes (one map or each cascade, the
// pre-pass, the measurement, overlays) on the shared scene_vertex.glsl with nothing to pay for
// undeformed meshes, and a caster that does not move is not deformed again.
#include "gl/gl_objects.h"
#include "gl/program.h"
#include "scenes/skinning.h"

#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab {

class GpuDeformer {
public:
    // `baseVertex[mesh][primitive]`: where each primitive starts in the vertex buffer.
    GpuDeformer(const Scene& scene, const std::vector<std::vector<GLint>>& baseVertex);
    bool empty() const { return instances_.empty(); }
    // Deforms the instances whose pose changed since the last call (all on the first) into
    // `vertexBuffer` and flags them in `moved` (one entry per Scene::instances). False with
    // `error` when the compute program cannot be built (the meshes then stay in their bind pose).
    bool update(const Scene& scene, GLuint vertexBuffer, std::vector<std::uint8_t>& moved, std::string& error);
    std::size_t deformedVertices() const { return vertices_; }

private:
    struct Job {  // one primitive of a deformed instance
        GLint source = 0, count = 0, destination = 0, targets = 0, targetCount = 0;
    };
    struct Deformed {
        std::size_t instance = 0;
        GLint jointFirst = -1, jointCount = 0, weightFirst = 0, weightCount = 0;
        std::vector<Job> jobs;
        Pose uploaded;  // the pose the vertex buffer holds
        bool fresh = true;
    };
    std::vector<Deformed> instances_;
    gl::Program program_;
    bool programTried_ = false;
    gl::Buffer sources_, targets_, joints_, weights_;
    std::vector<glm::mat4> jointData_;
    std::vector<float> weightData_;
    std::size_t vertices_ = 0;
};

}  // namespace shadowlab
