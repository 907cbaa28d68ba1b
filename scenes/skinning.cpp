#include "scenes/skinning.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

bool Mesh::morphed() const {
    return std::any_of(primitives.begin(), primitives.end(), [](const Primitive& p) { return !p.targets.empty(); });
}

bool Mesh::skinned() const {
    return std::any_of(primitives.begin(), primitives.end(), [](const Primitive& p) { return p.skinned(); });
}

std::vector<glm::dmat4> jointMatrices(const Scene& scene, const Skin& skin, const glm::dmat4& meshWorld) {
    std::vector<glm::dmat4> out(skin.joints.size(), glm::dmat4(1.0));
    const double det = glm::determinant(meshWorld);
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return out;
    const glm::dmat4 toMesh = glm::inverse(meshWorld);
    for (std::size_t j = 0; j < skin.joints.size(); ++j) {
        const int node = skin.joints[j];
        if (node < 0 || node >= int(scene.nodes.size())) continue;
        const glm::dmat4& inverseBind = j < skin.inverseBindMatrices.size() ? skin.inverseBindMatrices[j] : glm::dmat4(1.0);
        out[j] = toMesh * scene.nodes[std::size_t(node)].world * inverseBind;
    }
    return out;
}

bool isDeformed(const Scene& scene, const MeshInstance& instance) {
    if (instance.mesh < 0 || instance.mesh >= int(scene.meshes.size())) return false;
    const Mesh& mesh = scene.meshes[std::size_t(instance.mesh)];
    const bool skin = instance.node >= 0 && instance.node < int(scene.nodes.size()) &&
                      scene.nodes[std::size_t(instance.node)].skin >= 0 && mesh.skinned();
    return skin || mesh.morphed();
}

Pose instancePose(const Scene& scene, const MeshInstance& instance) {
    Pose pose;
    if (!isDeformed(scene, instance) || instance.node < 0 || instance.node >= int(scene.nodes.size())) return pose;
    const Node& node = scene.nodes[std::size_t(instance.node)];
    if (scene.meshes[std::size_t(instance.mesh)].morphed()) pose.weights = node.weights;
    if (node.skin >= 0 && node.skin < int(scene.skins.size()))
        pose.joints = jointMatrices(scene, scene.skins[std::size_t(node.skin)], instance.world);
    return pose;
}

glm::dvec3 skinPoint(const std::vector<glm::dmat4>& jointMatrices, const glm::u16vec4& joints, const glm::vec4& weights,
                     const glm::dvec3& position) {
    glm::dvec3 out(0.0);
    for (int k = 0; k < 4; ++k) {
        if (weights[k] == 0.0f) continue;
        const glm::dmat4& m = joints[k] < jointMatrices.size() ? jointMatrices[joints[k]] : glm::dmat4(1.0);
        out += double(weights[k]) * glm::dvec3(m * glm::dvec4(position, 1.0));
    }
    return out;
}

void deformPrimitive(const Primitive& p, const Pose& pose, std::vector<glm::vec3>& positions,
                     std::vector<glm::vec3>* normals) {
    const std::size_t n = p.positions.size();
    positions.resize(n);
    if (normals) normals->resize(n);
    const bool skinned = p.skinned() && !pose.joints.empty() && p.joints.size() == n && p.skinWeights.size() == n;
    for (std::size_t v = 0; v < n; ++v) {
        glm::dvec3 position(p.positions[v]);
        glm::dvec3 normal(v < p.normals.size() ? p.normals[v] : glm::vec3(0.0f, 0.0f, 1.0f));
        for (std::size_t t = 0; t < p.targets.size() && t < pose.weights.size(); ++t) {
            const double w = pose.weights[t];
            if (w == 0.0) continue;
            position += w * glm::dvec3(p.targets[t].positions[v]);
            if (!p.targets[t].normals.empty()) normal += w * glm::dvec3(p.targets[t].normals[v]);
        }
        if (skinned) {
            position = skinPoint(pose.joints, p.joints[v], p.skinWeights[v], position);
            // The blended linear part, as real-time skinning does (exact for rotations and uniform scale).
            normal = skinPoint(pose.joints, p.joints[v], p.skinWeights[v], normal) -
                     skinPoint(pose.joints, p.joints[v], p.skinWeights[v], glm::dvec3(0.0));
        }
        positions[v] = glm::vec3(position);
        if (normals) {
            const double length = glm::length(normal);
            (*normals)[v] = length > 0.0 && std::isfinite(length) ? glm::vec3(normal / length) : glm::vec3(0, 0, 1);
        }
    }
}

Aabb posedBounds(const Primitive& p, const Pose& pose) {
    // The morph displacement of any vertex lies in the weighted sum of the targets' boxes.
    glm::dvec3 lo(0.0), hi(0.0);
    for (std::size_t t = 0; t < p.targets.size() && t < pose.weights.size(); ++t) {
        const Aabb& d = p.targets[t].positionBounds;
        const double w = pose.weights[t];
        if (d.empty() || w == 0.0) continue;
        lo += w > 0.0 ? w * d.min : w * d.max;
        hi += w > 0.0 ? w * d.max : w * d.min;
    }
    auto widened = [&](const Aabb& box) {
        Aabb out;
        if (!box.empty()) out.extend(Aabb{box.min + lo, box.max + hi});
        return out;
    };
    if (!p.skinned() || pose.joints.empty()) return widened(p.bounds);
    Aabb out;
    for (std::size_t j = 0; j < p.jointBounds.size(); ++j) {
        const glm::dmat4& m = j < pose.joints.size() ? pose.joints[j] : glm::dmat4(1.0);
        out.extend(widened(p.jointBounds[j]).transformed(m));
    }
    return out;
}

Aabb deformedWorldBounds(const Scene& scene, const MeshInstance& instance) {
    const Pose pose = instancePose(scene, instance);
    Aabb out;
    for (const Primitive& p : scene.meshes[std::size_t(instance.mesh)].primitives)
        out.extend(posedBounds(p, pose).transformed(instance.world));
    return out;
}

}  // namespace shadowlab
