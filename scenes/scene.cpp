// Scene-model operations shared by the loader, the generators and animation: node transforms,
// instances and bounds, and the default light and camera.
#include "scenes/gltf_loader.h"
#include "scenes/scene.h"
#include "scenes/skinning.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <utility>

namespace shadowlab {

std::size_t Scene::triangleCount() const {
    std::size_t total = 0;
    for (const MeshInstance& instance : instances) {
        if (instance.mesh < 0 || instance.mesh >= int(meshes.size())) continue;
        for (const Primitive& p : meshes[std::size_t(instance.mesh)].primitives) total += p.triangleCount();
    }
    return total;
}

glm::dmat4 localTransform(const Node& node) {
    if (node.hasMatrix) return node.matrix;
    const glm::dmat4 t = glm::translate(glm::dmat4(1.0), glm::dvec3(node.translation));
    const glm::dmat4 r = glm::mat4_cast(glm::dquat(node.rotation));
    const glm::dmat4 s = glm::scale(glm::dmat4(1.0), glm::dvec3(node.scale));
    return t * r * s;
}

namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// True when the upper 3x3 is diagonal: then the transformed box is exactly the transformed
// vertices' box and the (per-frame) vertex loop can be skipped.
bool axisAligned(const glm::dmat4& m) {
    return m[0][1] == 0.0 && m[0][2] == 0.0 && m[1][0] == 0.0 && m[1][2] == 0.0 && m[2][0] == 0.0 &&
           m[2][1] == 0.0 && m[0][3] == 0.0 && m[1][3] == 0.0 && m[2][3] == 0.0 && m[3][3] == 1.0;
}

// Exact world bounds of a mesh: transforming the object box would overestimate rotated
// instances, and loose bounds make the light frustum (and so the shadow resolution) worse.
Aabb worldBoundsOf(const Mesh& mesh, const glm::dmat4& world) {
    Aabb out;
    const bool cheap = axisAligned(world);
    const glm::dmat3 linear(world);
    const glm::dvec3 offset(world[3]);
    for (const Primitive& p : mesh.primitives) {
        if (cheap || p.positions.empty()) {
            out.extend(p.bounds.transformed(world));
            continue;
        }
        for (const glm::vec3& v : p.positions) out.extend(linear * glm::dvec3(v) + offset);
    }
    return out;
}

// The node's frame without scale or shear (cameras look down -Z of an orthonormal frame).
glm::dmat4 rigidFrame(const glm::dmat4& world) {
    const glm::dvec3 back = glm::normalize(glm::dvec3(world[2]));
    const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(world[1]), back));
    const glm::dvec3 up = glm::cross(back, right);
    if (!finite(back) || !finite(right) || !finite(up)) return world;
    glm::dmat4 out(1.0);
    out[0] = glm::dvec4(right, 0.0);
    out[1] = glm::dvec4(up, 0.0);
    out[2] = glm::dvec4(back, 0.0);
    out[3] = world[3];
    return out;
}

}  // namespace

void updateWorldTransforms(Scene& scene) {
    const int nodeCount = int(scene.nodes.size());
    if (nodeCount == 0) {
        // Scenes built without a node tree (instances only): refresh what can be derived.
        scene.bounds = Aabb{};
        for (MeshInstance& instance : scene.instances) {
            if (instance.mesh >= 0 && instance.mesh < int(scene.meshes.size()))
                instance.worldBounds = worldBoundsOf(scene.meshes[std::size_t(instance.mesh)], instance.world);
            instance.mirrored = glm::determinant(glm::dmat3(instance.world)) < 0.0;
            scene.bounds.extend(instance.worldBounds);
        }
        return;
    }

    std::vector<int> roots = scene.roots;
    if (roots.empty())
        for (int i = 0; i < nodeCount; ++i)
            if (scene.nodes[std::size_t(i)].parent < 0) roots.push_back(i);

    scene.instances.clear();
    scene.bounds = Aabb{};
    std::vector<char> visited(std::size_t(nodeCount), 0);
    // Depth-first, pre-order, children in file order: instance order is stable across calls.
    std::vector<std::pair<int, glm::dmat4>> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, glm::dmat4(1.0));
    while (!stack.empty()) {
        auto [index, parentWorld] = stack.back();
        stack.pop_back();
        if (index < 0 || index >= nodeCount || visited[std::size_t(index)]) continue;  // cycles, bad links
        visited[std::size_t(index)] = 1;
        Node& node = scene.nodes[std::size_t(index)];
        node.world = parentWorld * localTransform(node);

        if (node.mesh >= 0 && node.mesh < int(scene.meshes.size())) {
            MeshInstance instance;
            instance.node = index;
            instance.mesh = node.mesh;
            instance.world = node.world;
            instance.mirrored = glm::determinant(glm::dmat3(node.world)) < 0.0;
            // A deformed mesh's bounds need every joint's world matrix: after the traversal.
            if (!isDeformed(scene, instance)) {
                instance.worldBounds = worldBoundsOf(scene.meshes[std::size_t(node.mesh)], node.world);
                scene.bounds.extend(instance.worldBounds);
            }
            scene.instances.push_back(std::move(instance));
        }
        if (node.light >= 0 && node.light < int(scene.lights.size())) {
            Light& light = scene.lights[std::size_t(node.light)];
            light.position = glm::dvec3(node.world[3]);
            const glm::dvec3 direction = glm::dmat3(node.world) * glm::dvec3(0.0, 0.0, -1.0);
            const double length = glm::length(direction);
            if (std::isfinite(length) && length > 0.0) light.direction = direction / length;
        }
        if (node.camera >= 0 && node.camera < int(scene.cameras.size()))
            scene.cameras[std::size_t(node.camera)].cameraToWorld = rigidFrame(node.world);

        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
            stack.emplace_back(*child, node.world);
    }
    for (MeshInstance& instance : scene.instances)
        if (isDeformed(scene, instance)) {
            instance.worldBounds = deformedWorldBounds(scene, instance);
            scene.bounds.extend(instance.worldBounds);
        }
}

void addDefaultsIfMissing(Scene& scene) {
    glm::dvec3 center(0.0);
    double radius = 1.0;
    if (!scene.bounds.empty()) {
        center = scene.bounds.center();
        radius = 0.5 * glm::length(scene.bounds.extent());
        if (!std::isfinite(radius) || radius <= 0.0) radius = 1.0;  // a single point, or overflow
        if (!finite(center)) center = glm::dvec3(0.0);
    }

    if (scene.lights.empty()) {
        Light sun;
        sun.name = "Default Sun";
        sun.type = LightType::Directional;
        sun.intensity = 3.0f;
        // From above and slightly sideways: long enough shadows to be seen, never grazing.
        sun.direction = glm::normalize(glm::dvec3(0.35, -1.0, 0.25));
        sun.position = center - sun.direction * (2.0 * radius);
        sun.node = -1;
        scene.lights.push_back(sun);
        scene.defaultLight = true;
    }

    if (scene.cameras.empty()) {
        Camera camera;
        camera.name = "Framing Camera";
        camera.orthographic = false;
        camera.yfov = float(glm::radians(60.0));
        // Far enough that the bounding sphere fits the vertical field of view.
        const double distance = radius / std::sin(0.5 * double(camera.yfov)) * 1.05;
        const glm::dvec3 eye = center + glm::normalize(glm::dvec3(1.0, 0.75, 1.0)) * distance;
        camera.cameraToWorld = glm::inverse(glm::lookAt(eye, center, glm::dvec3(0.0, 1.0, 0.0)));
        camera.znear = float(std::max(0.5 * (distance - radius), 1e-3 * radius));
        camera.zfar = float((distance + radius) * 1.5);
        camera.node = -1;
        scene.cameras.push_back(camera);
        scene.defaultCamera = true;
    }
}

}  // namespace shadowlab
