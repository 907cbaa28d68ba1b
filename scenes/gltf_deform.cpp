// Skins and morph targets (glTF 2.0 spec 3.7.3 "Skins", 3.7.2.2 "Morph Targets"): the skins'
// joints and inverse bind matrices, the primitives' JOINTS_0 / WEIGHTS_0 and target
// displacements, each checked (counts, ranges, finite values) before use, and the nodes' weights.
#include "scenes/gltf_internal.h"

#include <algorithm>
#include <cmath>

namespace shadowlab::gltf {
namespace {

bool meshDeformedAt(const Scene& scene, const Node& node) {
    if (node.mesh < 0 || node.mesh >= int(scene.meshes.size())) return false;
    const Mesh& mesh = scene.meshes[std::size_t(node.mesh)];
    return mesh.morphed() || (node.skin >= 0 && mesh.skinned());
}

}  // namespace

void Converter::convertSkins() {
    for (std::size_t i = 0; i < m.skins.size(); ++i) {
        const tinygltf::Skin& src = m.skins[i];
        const std::string where = label("skin", i, src.name);
        Skin skin;
        skin.name = src.name;
        if (src.joints.empty()) fail(where + ": has no joints");
        for (int joint : src.joints) {
            if (joint < 0 || std::size_t(joint) >= m.nodes.size())
                fail(where + ": joint node " + std::to_string(joint) + " does not exist");
            skin.joints.push_back(joint);
        }
        if (src.skeleton >= int(m.nodes.size()) || src.skeleton < -1)
            fail(where + ": skeleton node " + std::to_string(src.skeleton) + " does not exist");
        skin.skeleton = src.skeleton;
        skin.inverseBindMatrices.assign(skin.joints.size(), glm::dmat4(1.0));  // the spec's default
        if (src.inverseBindMatrices >= 0) {
            const std::string what = where + " inverseBindMatrices";
            if (std::size_t(src.inverseBindMatrices) < m.accessors.size() &&
                m.accessors[std::size_t(src.inverseBindMatrices)].count < skin.joints.size())
                fail(what + ": fewer matrices than the skin's " + std::to_string(skin.joints.size()) + " joints");
            std::size_t count = 0;
            const std::vector<double> values = readAccessor(src.inverseBindMatrices, what, 16, false, count);
            if (!finiteAll(values)) fail(what + ": non-finite values");
            for (std::size_t j = 0; j < skin.joints.size(); ++j)
                for (int c = 0; c < 4; ++c)
                    for (int r = 0; r < 4; ++r) skin.inverseBindMatrices[j][c][r] = values[j * 16 + std::size_t(c * 4 + r)];
        }
        scene.skins.push_back(std::move(skin));
    }
}

void Converter::readSkinAttributes(const tinygltf::Primitive& src, const std::string& where, Primitive& p) {
    const auto jointsIt = src.attributes.find("JOINTS_0"), weightsIt = src.attributes.find("WEIGHTS_0");
    const bool hasJoints = jointsIt != src.attributes.end(), hasWeights = weightsIt != src.attributes.end();
    if (!hasJoints && !hasWeights) return;
    if (hasJoints != hasWeights) {
        warn(where + ": JOINTS_0 without WEIGHTS_0 (or the reverse), drawn unskinned");
        return;
    }
    if (src.attributes.count("JOINTS_1"))
        warn(where + ": JOINTS_1 / WEIGHTS_1 ignored, only the first 4 influences per vertex are used");
    const std::size_t vertexCount = p.positions.size();
    // Declared counts first: a wrong count is refused before anything is decoded.
    for (const auto& [name, accessor] : {std::pair<const char*, int>{"JOINTS_0", jointsIt->second}, {"WEIGHTS_0", weightsIt->second}})
        if (accessor >= 0 && std::size_t(accessor) < m.accessors.size() &&
            m.accessors[std::size_t(accessor)].count != vertexCount)
            fail(where + ": " + name + " has " + std::to_string(m.accessors[std::size_t(accessor)].count) +
                 " entries but POSITION has " + std::to_string(vertexCount));
    std::size_t count = 0;
    const std::vector<double> joints = readAccessor(jointsIt->second, where + " JOINTS_0", 4, true, count);
    const std::vector<double> weights = readAccessor(weightsIt->second, where + " WEIGHTS_0", 4, false, count);
    if (!finiteAll(weights)) fail(where + ": non-finite WEIGHTS_0 values");
    p.joints.resize(vertexCount);
    p.skinWeights.resize(vertexCount);
    for (std::size_t v = 0; v < vertexCount; ++v) {
        glm::dvec4 w(0.0);
        for (int k = 0; k < 4; ++k) {
            const double j = joints[v * 4 + std::size_t(k)];
            if (j > 65535.0) fail(where + ": JOINTS_0 index " + std::to_string(std::uint64_t(j)) + " is out of range");
            p.joints[v][k] = std::uint16_t(j);
            w[k] = std::max(0.0, weights[v * 4 + std::size_t(k)]);
        }
        // The spec asks for weights summing to 1; exporters round. A vertex without any weight
        // follows its first joint rather than collapsing to the origin.
        const double sum = w.x + w.y + w.z + w.w;
        p.skinWeights[v] = sum > 0.0 ? glm::vec4(w / sum) : glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
        for (int k = 0; k < 4; ++k) {
            if (p.skinWeights[v][k] <= 0.0f) continue;
            const std::size_t j = p.joints[v][k];
            if (j >= p.jointBounds.size()) p.jointBounds.resize(j + 1);
            p.jointBounds[j].extend(glm::dvec3(p.positions[v]));
        }
    }
}

void Converter::readMorphTargets(const tinygltf::Primitive& src, const std::string& where, Primitive& p) const {
    const std::size_t vertexCount = p.positions.size();
    for (std::size_t t = 0; t < src.targets.size(); ++t) {
        const std::string what = where + " morph target " + std::to_string(t);
        MorphTarget target;
        for (const char* name : {"POSITION", "NORMAL"}) {
            const auto it = src.targets[t].find(name);
            if (it == src.targets[t].end()) continue;
            if (it->second >= 0 && std::size_t(it->second) < m.accessors.size() &&
                m.accessors[std::size_t(it->second)].count != vertexCount)
                fail(what + ": " + name + " has " + std::to_string(m.accessors[std::size_t(it->second)].count) +
                     " entries but the primitive has " + std::to_string(vertexCount) + " vertices");
            std::size_t count = 0;
            const std::vector<double> values = readAccessor(it->second, what + " " + name, 3, false, count);
            if (!finiteAll(values)) fail(what + ": non-finite " + name + " displacements");
            std::vector<glm::vec3>& out = name[0] == 'P' ? target.positions : target.normals;
            out.resize(vertexCount);
            for (std::size_t v = 0; v < vertexCount; ++v)
                out[v] = glm::vec3(float(values[3 * v]), float(values[3 * v + 1]), float(values[3 * v + 2]));
        }
        if (target.positions.empty()) target.positions.assign(vertexCount, glm::vec3(0.0f));
        for (const glm::vec3& d : target.positions) target.positionBounds.extend(glm::dvec3(d));
        p.targets.push_back(std::move(target));
    }
}

int Converter::morphTargetCount(int node) const {
    if (node < 0 || std::size_t(node) >= scene.nodes.size()) return 0;
    const int mesh = scene.nodes[std::size_t(node)].mesh;
    if (mesh < 0 || std::size_t(mesh) >= scene.meshes.size()) return 0;
    std::size_t targets = 0;
    for (const Primitive& p : scene.meshes[std::size_t(mesh)].primitives) targets = std::max(targets, p.targets.size());
    return int(targets);
}

void Converter::finishDeformedNodes() {
    for (std::size_t i = 0; i < m.meshes.size() && i < scene.meshes.size(); ++i) {
        const std::vector<double>& w = m.meshes[i].weights;
        if (!finiteAll(w)) fail(label("mesh", i, m.meshes[i].name) + ": non-finite morph weights");
        scene.meshes[i].weights.assign(w.begin(), w.end());
    }
    std::vector<char> meshTaken(scene.meshes.size(), 0);
    std::uint64_t copiedVertices = 0;
    for (int index : reachableOrder) {
        const auto i = std::size_t(index);
        Node& node = scene.nodes[i];
        const tinygltf::Node& src = m.nodes[i];
        const std::string where = label("node", i, src.name);
        if (src.skin >= int(scene.skins.size()) || src.skin < -1)
            fail(where + ": skin " + std::to_string(src.skin) + " does not exist");
        node.skin = node.mesh >= 0 ? src.skin : -1;
        if (node.mesh < 0) continue;
        const Mesh& mesh = scene.meshes[std::size_t(node.mesh)];
        if (node.skin >= 0) {
            const std::size_t joints = scene.skins[std::size_t(node.skin)].joints.size();
            for (const Primitive& p : mesh.primitives)
                if (p.jointBounds.size() > joints)
                    fail(where + ": its mesh uses joint " + std::to_string(p.jointBounds.size() - 1) + " but skin " +
                         std::to_string(node.skin) + " has " + std::to_string(joints) + " joints");
        }
        if (const int targets = morphTargetCount(index); targets > 0) {
            if (!finiteAll(src.weights)) fail(where + ": non-finite morph weights");
            if (!src.weights.empty())
                node.weights.assign(src.weights.begin(), src.weights.end());
            else
                node.weights = mesh.weights;
            node.weights.resize(std::size_t(targets), 0.0f);
        }
        if (!meshDeformedAt(scene, node)) continue;
        if (!meshTaken[std::size_t(node.mesh)]) {
            meshTaken[std::size_t(node.mesh)] = 1;
            continue;
        }
        // A second node drawing a deformed mesh gets its own copy: its pose moves its own vertices.
        for (const Primitive& p : mesh.primitives) copiedVertices += p.positions.size();
        if (copiedVertices > options.limits.vertices)
            fail("the deformed meshes drawn by several nodes copy " + std::to_string(copiedVertices) +
                 " vertices, which " + overLimit("vertices", options.limits.vertices));
        scene.meshes.push_back(mesh);
        node.mesh = int(scene.meshes.size() - 1);
        meshTaken.push_back(1);
    }
}

}  // namespace shadowlab::gltf
