#pragma once
// Scenes built in code for renderer tests: no loader, no files, exact known geometry.
#include "scenes/scene.h"

#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab::test {

// An axis-aligned box [lo, hi] as 12 outward-facing triangles with flat normals.
inline Primitive boxPrimitive(glm::vec3 lo, glm::vec3 hi, int material) {
    Primitive p;
    p.material = material;
    const glm::vec3 n[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const glm::vec3& normal : n) {
        // Two tangents with t1 x t2 = normal, so the quad winds counter-clockwise seen from outside.
        const glm::vec3 t1 = glm::abs(normal.y) > 0.5f ? glm::vec3(0, 0, normal.y) : glm::vec3(-normal.z, 0, normal.x);
        const glm::vec3 t2 = glm::cross(normal, t1);
        const glm::vec3 c = (lo + hi) * 0.5f, h = (hi - lo) * 0.5f;
        const auto base = std::uint32_t(p.positions.size());
        for (auto [a, b] : {std::pair{-1.f, -1.f}, {1.f, -1.f}, {1.f, 1.f}, {-1.f, 1.f}}) {
            p.positions.push_back(c + h * (normal + a * t1 + b * t2));
            p.normals.push_back(normal);
            p.texcoords.push_back({a * 0.5f + 0.5f, b * 0.5f + 0.5f});
        }
        for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) p.indices.push_back(base + i);
    }
    for (const glm::vec3& v : p.positions) p.bounds.extend(glm::dvec3(v));
    return p;
}

inline void addInstance(Scene& scene, int mesh, const glm::dmat4& world) {
    MeshInstance inst;
    inst.mesh = mesh;
    inst.node = int(scene.nodes.size());
    inst.world = world;
    for (const Primitive& p : scene.meshes[std::size_t(mesh)].primitives) inst.worldBounds.extend(p.bounds.transformed(world));
    inst.mirrored = glm::determinant(world) < 0.0;
    Node node;
    node.name = "node" + std::to_string(scene.nodes.size());
    node.mesh = mesh;
    node.world = world;
    scene.nodes.push_back(node);
    scene.instances.push_back(inst);
    scene.bounds.extend(inst.worldBounds);
}

// Ground 20 x 20 (a thin box, top at y = 0), a 2 m box centred at (0, 1, 0), a sun from above.
inline Scene planeBoxScene(glm::dvec3 sunDirection = {-0.3, -1.0, -0.2}) {
    Scene s;
    s.materials.push_back({"Ground", {0.8f, 0.8f, 0.8f, 1.0f}});
    s.materials.push_back({"Box", {0.8f, 0.1f, 0.1f, 1.0f}});
    s.meshes.push_back({"Ground", {boxPrimitive({-10, -0.1f, -10}, {10, 0, 10}, 0)}});
    s.meshes.push_back({"Box", {boxPrimitive({-1, 0, -1}, {1, 2, 1}, 1)}});
    addInstance(s, 0, glm::dmat4(1.0));
    addInstance(s, 1, glm::dmat4(1.0));
    Light sun;
    sun.name = "Sun";
    sun.direction = glm::normalize(sunDirection);
    s.lights.push_back(sun);
    return s;
}

}  // namespace shadowlab::test
