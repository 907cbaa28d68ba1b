#include "resources/gpu_deform.h"

#include <algorithm>

namespace shadowlab {
namespace {

// DeformSource of shaders/deform.comp (std430, 64 bytes).
struct DeformSource {
    glm::vec4 position;
    glm::vec4 normal;
    glm::uvec4 joints;
    glm::vec4 weights;
};

template <class T>
gl::Buffer staticBuffer(const std::vector<T>& data, GLbitfield flags = 0) {
    gl::Buffer buffer = gl::createBuffer();
    glNamedBufferStorage(buffer.id(), GLsizeiptr(std::max<std::size_t>(1, data.size()) * sizeof(T)),
                         data.empty() ? nullptr : data.data(), flags);
    return buffer;
}

}  // namespace

GpuDeformer::GpuDeformer(const Scene& scene, const std::vector<std::vector<GLint>>& baseVertex) {
    std::vector<DeformSource> sources;
    std::vector<glm::vec4> deltas;
    GLint joints = 0, weights = 0;
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const MeshInstance& instance = scene.instances[i];
        if (!isDeformed(scene, instance) || std::size_t(instance.mesh) >= baseVertex.size()) continue;
        Deformed d;
        d.instance = i;
        const Pose pose = instancePose(scene, instance);
        if (!pose.joints.empty()) {
            d.jointFirst = joints;
            d.jointCount = GLint(pose.joints.size());
            joints += d.jointCount;
        }
        d.weightFirst = weights;
        d.weightCount = GLint(pose.weights.size());
        weights += d.weightCount;
        const std::vector<Primitive>& primitives = scene.meshes[std::size_t(instance.mesh)].primitives;
        for (std::size_t k = 0; k < primitives.size() && k < baseVertex[std::size_t(instance.mesh)].size(); ++k) {
            const Primitive& p = primitives[k];
            Job job;
            job.source = GLint(sources.size());
            job.count = GLint(p.positions.size());
            job.destination = baseVertex[std::size_t(instance.mesh)][k];
            job.targets = GLint(deltas.size());
            job.targetCount = GLint(std::min(p.targets.size(), pose.weights.size()));
            for (std::size_t v = 0; v < p.positions.size(); ++v) {
                DeformSource s{glm::vec4(p.positions[v], 1.0f),
                               glm::vec4(v < p.normals.size() ? p.normals[v] : glm::vec3(0, 0, 1), 0.0f),
                               glm::uvec4(0u), glm::vec4(1.0f, 0.0f, 0.0f, 0.0f)};
                if (p.skinned() && v < p.joints.size() && v < p.skinWeights.size()) {
                    s.joints = glm::uvec4(p.joints[v]);
                    s.weights = p.skinWeights[v];
                }
                sources.push_back(s);
            }
            for (GLint t = 0; t < job.targetCount; ++t) {
                const MorphTarget& target = p.targets[std::size_t(t)];
                for (std::size_t v = 0; v < p.positions.size(); ++v) {
                    deltas.push_back(glm::vec4(target.positions[v], 0.0f));
                    deltas.push_back(glm::vec4(v < target.normals.size() ? target.normals[v] : glm::vec3(0.0f), 0.0f));
                }
            }
            d.jobs.push_back(job);
        }
        instances_.push_back(std::move(d));
    }
    if (instances_.empty()) return;
    sources_ = staticBuffer(sources);
    targets_ = staticBuffer(deltas);
    jointData_.assign(std::size_t(joints), glm::mat4(1.0f));
    weightData_.assign(std::size_t(weights), 0.0f);
    joints_ = staticBuffer(jointData_, GL_DYNAMIC_STORAGE_BIT);
    weights_ = staticBuffer(weightData_, GL_DYNAMIC_STORAGE_BIT);
}

bool GpuDeformer::update(const Scene& scene, GLuint vertexBuffer, std::vector<std::uint8_t>& moved, std::string& error) {
    if (instances_.empty()) return true;
    if (!programTried_) {
        programTried_ = true;
        if (auto p = gl::Program::buildCompute("deform.comp", "", error)) program_ = std::move(*p);
    }
    if (!program_) return false;
    // Poses first (CPU, O(joints)): only the instances whose pose changed are dispatched.
    std::vector<Deformed*> changed;
    for (Deformed& d : instances_) {
        if (d.instance >= scene.instances.size()) continue;
        Pose pose = instancePose(scene, scene.instances[d.instance]);
        if (pose.joints.size() != std::size_t(d.jointCount) || pose.weights.size() != std::size_t(d.weightCount))
            continue;  // the scene no longer matches its upload (a renderer must be given the scene again)
        if (!d.fresh && pose.joints == d.uploaded.joints && pose.weights == d.uploaded.weights) continue;
        for (std::size_t j = 0; j < pose.joints.size(); ++j) jointData_[std::size_t(d.jointFirst) + j] = glm::mat4(pose.joints[j]);
        std::copy(pose.weights.begin(), pose.weights.end(), weightData_.begin() + d.weightFirst);
        d.uploaded = std::move(pose);
        d.fresh = false;
        changed.push_back(&d);
        if (d.instance < moved.size()) moved[d.instance] = 1;
    }
    if (changed.empty()) return true;
    if (!jointData_.empty())
        glNamedBufferSubData(joints_.id(), 0, GLsizeiptr(jointData_.size() * sizeof(glm::mat4)), jointData_.data());
    if (!weightData_.empty())
        glNamedBufferSubData(weights_.id(), 0, GLsizeiptr(weightData_.size() * sizeof(float)), weightData_.data());
    program_.use();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 8, sources_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 9, targets_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 10, joints_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 11, weights_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 12, vertexBuffer);
    constexpr GLuint kGroup = 64;  // local_size_x of deform.comp
    for (const Deformed* d : changed) {
        program_.set("jointFirst", d->jointFirst);
        program_.set("jointCount", d->jointCount);
        program_.set("weightFirst", d->weightFirst);
        for (const Job& job : d->jobs) {
            if (job.count == 0) continue;
            program_.set("vertexCount", job.count);
            program_.set("sourceFirst", job.source);
            program_.set("targetFirst", job.targets);
            program_.set("targetCount", job.targetCount);
            program_.set("destinationFirst", job.destination);
            glDispatchCompute((GLuint(job.count) + kGroup - 1) / kGroup, 1, 1);
            vertices_ += std::size_t(job.count);
        }
    }
    // The draws that follow read the written vertices as attributes.
    glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);
    for (GLuint binding = 8; binding <= 12; ++binding) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);
    glUseProgram(0);
    return true;
}

}  // namespace shadowlab
