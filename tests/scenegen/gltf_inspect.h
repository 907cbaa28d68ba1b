#pragma once
// Reads a generated .glb back with tinygltf and counts it independently of the generator code:
// world transforms from the node hierarchy, drawn triangles, bounds from the vertex data.
#include <tiny_gltf.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/quaternion.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace shadowlab::test {

struct InspectedNode {
    int index = -1;
    std::string name;
    int parent = -1;
    int mesh = -1, camera = -1, light = -1;
    glm::dmat4 world{1.0};
    glm::dvec3 position() const { return glm::dvec3(world[3]); }
    glm::dvec3 forward() const { return glm::normalize(glm::dvec3(world * glm::dvec4(0, 0, -1, 0))); }  // camera/light -Z
};

struct Inspected {
    tinygltf::Model model;
    std::string error;
    std::vector<InspectedNode> nodes;  // reachable from the scene, in depth-first order
    std::size_t meshInstances = 0;
    std::size_t triangles = 0;
    glm::dvec3 lo{std::numeric_limits<double>::max()}, hi{std::numeric_limits<double>::lowest()};

    const InspectedNode* node(const std::string& name) const {
        for (const InspectedNode& n : nodes)
            if (n.name == name) return &n;
        return nullptr;
    }
    std::vector<const InspectedNode*> childrenOf(const std::string& name) const {
        std::vector<const InspectedNode*> out;
        const InspectedNode* p = node(name);
        for (const InspectedNode& n : nodes)
            if (p && n.parent == p->index) out.push_back(&n);
        return out;
    }
};

inline std::vector<glm::vec3> readVec3(const tinygltf::Model& m, int accessorIndex) {
    const tinygltf::Accessor& a = m.accessors.at(std::size_t(accessorIndex));
    const tinygltf::BufferView& v = m.bufferViews.at(std::size_t(a.bufferView));
    const auto& data = m.buffers.at(std::size_t(v.buffer)).data;
    const std::size_t stride = v.byteStride ? v.byteStride : 12;
    std::vector<glm::vec3> out(a.count);
    for (std::size_t i = 0; i < a.count; ++i) std::memcpy(&out[i], data.data() + v.byteOffset + a.byteOffset + i * stride, 12);
    return out;
}

inline std::vector<std::uint32_t> readIndices(const tinygltf::Model& m, int accessorIndex) {
    const tinygltf::Accessor& a = m.accessors.at(std::size_t(accessorIndex));
    const tinygltf::BufferView& v = m.bufferViews.at(std::size_t(a.bufferView));
    const unsigned char* p = m.buffers.at(std::size_t(v.buffer)).data.data() + v.byteOffset + a.byteOffset;
    std::vector<std::uint32_t> out(a.count);
    for (std::size_t i = 0; i < a.count; ++i) {
        if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
            std::uint16_t s;
            std::memcpy(&s, p + 2 * i, 2);
            out[i] = s;
        } else {
            std::memcpy(&out[i], p + 4 * i, 4);
        }
    }
    return out;
}

inline glm::dmat4 nodeLocal(const tinygltf::Node& n) {
    if (n.matrix.size() == 16) {
        glm::dmat4 m;
        for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = n.matrix[std::size_t(i)];
        return m;
    }
    glm::dmat4 m(1.0);
    if (n.translation.size() == 3) m = glm::translate(m, {n.translation[0], n.translation[1], n.translation[2]});
    if (n.rotation.size() == 4) m *= glm::toMat4(glm::dquat(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]));
    if (n.scale.size() == 3) m = glm::scale(m, {n.scale[0], n.scale[1], n.scale[2]});
    return m;
}

inline std::size_t meshTriangles(const tinygltf::Model& m, int mesh) {
    std::size_t t = 0;
    for (const tinygltf::Primitive& p : m.meshes.at(std::size_t(mesh)).primitives)
        t += m.accessors.at(std::size_t(p.indices)).count / 3;
    return t;
}

inline int nodeLight(const tinygltf::Node& n) {
    auto it = n.extensions.find("KHR_lights_punctual");
    if (it == n.extensions.end() || !it->second.Has("light")) return -1;
    return it->second.Get("light").GetNumberAsInt();
}

inline Inspected inspect(const std::filesystem::path& file, bool withBounds = true) {
    Inspected r;
    tinygltf::TinyGLTF loader;
    std::string warn;
    if (!loader.LoadBinaryFromFile(&r.model, &r.error, &warn, file.string())) {
        if (r.error.empty()) r.error = "tinygltf could not read " + file.string();
        return r;
    }
    const tinygltf::Model& m = r.model;
    std::vector<glm::dvec3> meshLo(m.meshes.size()), meshHi(m.meshes.size());
    std::vector<std::vector<glm::vec3>> meshPositions(m.meshes.size());
    for (std::size_t i = 0; withBounds && i < m.meshes.size(); ++i)
        for (const tinygltf::Primitive& p : m.meshes[i].primitives) {
            auto pos = readVec3(m, p.attributes.at("POSITION"));
            meshPositions[i].insert(meshPositions[i].end(), pos.begin(), pos.end());
        }
    struct Item {
        int index, parent;
        glm::dmat4 parentWorld;
    };
    std::vector<Item> stack;
    const tinygltf::Scene& scene = m.scenes.at(std::size_t(std::max(0, m.defaultScene)));
    for (auto it = scene.nodes.rbegin(); it != scene.nodes.rend(); ++it) stack.push_back({*it, -1, glm::dmat4(1.0)});
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        const tinygltf::Node& n = m.nodes.at(std::size_t(item.index));
        InspectedNode in;
        in.index = item.index;
        in.name = n.name;
        in.parent = item.parent;
        in.mesh = n.mesh;
        in.camera = n.camera;
        in.light = nodeLight(n);
        in.world = item.parentWorld * nodeLocal(n);
        if (n.mesh >= 0) {
            ++r.meshInstances;
            r.triangles += meshTriangles(m, n.mesh);
            for (const glm::vec3& p : meshPositions[std::size_t(n.mesh)]) {
                const glm::dvec3 w(in.world * glm::dvec4(glm::dvec3(p), 1.0));
                r.lo = glm::min(r.lo, w);
                r.hi = glm::max(r.hi, w);
            }
        }
        r.nodes.push_back(in);
        for (auto it = n.children.rbegin(); it != n.children.rend(); ++it) stack.push_back({*it, item.index, in.world});
    }
    return r;
}

inline std::string readBytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace shadowlab::test
