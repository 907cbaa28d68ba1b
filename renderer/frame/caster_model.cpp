#include "frame/caster_model.h"

#include "math/random.h"
#include "math/ray_box.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace shadowlab {

namespace {

struct WorldTriangle {
    glm::dvec3 a, b, c;
};

std::vector<WorldTriangle> worldTriangles(const Scene& scene, const MeshInstance& inst, std::size_t limit) {
    std::vector<WorldTriangle> out;
    if (inst.mesh < 0 || inst.mesh >= int(scene.meshes.size())) return out;
    for (const Primitive& prim : scene.meshes[std::size_t(inst.mesh)].primitives) {
        const std::size_t count = prim.positions.size();
        for (std::size_t i = 0; i + 2 < prim.indices.size(); i += 3) {
            if (out.size() >= limit) return out;
            const std::uint32_t ia = prim.indices[i], ib = prim.indices[i + 1], ic = prim.indices[i + 2];
            if (ia >= count || ib >= count || ic >= count) continue;
            auto world = [&](std::uint32_t v) {
                return glm::dvec3(inst.world * glm::dvec4(glm::dvec3(prim.positions[v]), 1.0));
            };
            out.push_back({world(ia), world(ib), world(ic)});
        }
    }
    return out;
}

std::size_t triangleCount(const Scene& scene, const MeshInstance& inst) {
    std::size_t n = 0;
    if (inst.mesh >= 0 && inst.mesh < int(scene.meshes.size()))
        for (const Primitive& prim : scene.meshes[std::size_t(inst.mesh)].primitives) n += prim.indices.size() / 3;
    return n;
}

// Moeller-Trumbore distance along the ray, either side; infinity on a miss.
double rayDistance(const WorldTriangle& t, const glm::dvec3& origin, const glm::dvec3& dir) {
    const glm::dvec3 e1 = t.b - t.a, e2 = t.c - t.a;
    const glm::dvec3 p = glm::cross(dir, e2);
    const double det = glm::dot(e1, p);
    const double miss = std::numeric_limits<double>::infinity();
    if (std::abs(det) < 1e-300) return miss;
    const double inv = 1.0 / det;
    const glm::dvec3 s = origin - t.a;
    const double u = glm::dot(s, p) * inv;
    if (u < 0.0 || u > 1.0) return miss;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(dir, q) * inv;
    if (v < 0.0 || u + v > 1.0) return miss;
    const double d = glm::dot(e2, q) * inv;
    return d > 0.0 ? d : miss;
}

// Does the ray hit the triangle (either side) beyond tMin?
bool rayHits(const WorldTriangle& t, const glm::dvec3& origin, const glm::dvec3& dir, double tMin) {
    const double d = rayDistance(t, origin, dir);
    return d > tMin && d < std::numeric_limits<double>::infinity();
}

// The sky the backdrop rule tests: straight up, a Fibonacci spiral over the hemisphere above 10
// degrees of elevation, and the scene's own directional lights (a room's sun through its window).
std::vector<glm::dvec3> skyDirections(const Scene& scene) {
    std::vector<glm::dvec3> dirs{{0.0, 1.0, 0.0}};
    constexpr int kSpiral = 48;
    const double minY = std::sin(glm::radians(10.0));
    const double golden = glm::pi<double>() * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < kSpiral; ++i) {
        const double y = minY + (1.0 - minY) * (double(i) + 0.5) / kSpiral;
        const double r = std::sqrt(std::max(0.0, 1.0 - y * y));
        dirs.push_back({r * std::cos(golden * i), y, r * std::sin(golden * i)});
    }
    for (const Light& light : scene.lights)
        if (light.type == LightType::Directional && glm::length(light.direction) > 0.0)
            dirs.push_back(-glm::normalize(light.direction));
    return dirs;
}

// Area-weighted points on every instance but `skip`, deterministic.
std::vector<glm::dvec3> surfaceSamples(const Scene& scene, std::size_t skip, std::size_t count) {
    std::vector<WorldTriangle> triangles;
    std::vector<double> cumulative;
    double total = 0.0;
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        if (i == skip) continue;
        for (const WorldTriangle& t : worldTriangles(scene, scene.instances[i], 20000)) {
            const double area = 0.5 * glm::length(glm::cross(t.b - t.a, t.c - t.a));
            if (!(area > 0.0)) continue;
            total += area;
            triangles.push_back(t);
            cumulative.push_back(total);
        }
    }
    std::vector<glm::dvec3> points;
    if (triangles.empty()) return points;
    Rng rng(0x5EEDu);
    for (std::size_t k = 0; k < count; ++k) {
        const double pick = rng.uniform() * total;
        const std::size_t j = std::min<std::size_t>(
            std::size_t(std::lower_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin()),
            triangles.size() - 1);
        double u = rng.uniform(), v = rng.uniform();
        if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
        const WorldTriangle& t = triangles[j];
        points.push_back(t.a + u * (t.b - t.a) + v * (t.c - t.a));
    }
    return points;
}

// A shell that holds every other instance holds their union, so its bounds are the union of all:
// one pass over the instances finds the candidates.
bool holdsAllOthers(const Scene& scene, const Aabb& all, std::size_t candidate) {
    const Aabb& box = scene.instances[candidate].worldBounds;
    if (box.empty() || all.empty()) return false;
    const double slack = 1e-6 * std::max(1.0, glm::length(all.extent()));
    return !glm::any(glm::lessThan(all.min, box.min - slack)) && !glm::any(glm::greaterThan(all.max, box.max + slack));
}

}  // namespace

CasterFaces resolvedFaces(CasterFaces setting) {
    // Auto: both sides (docs/caster-model.md: the same E_total as front faces on forest, street and
    // Sponza, and closed single-sided rooms shadowed).
    return setting == CasterFaces::Auto ? CasterFaces::Both : setting;
}

std::vector<std::size_t> detectBackdrops(const Scene& scene, std::size_t maxTriangles) {
    std::vector<std::size_t> found;
    if (scene.instances.size() < 2) return found;
    Aabb all;
    for (const MeshInstance& inst : scene.instances) all.extend(inst.worldBounds);
    const double scale = std::max(1e-9, glm::length(all.extent()));
    for (std::size_t c = 0; c < scene.instances.size(); ++c) {
        if (!holdsAllOthers(scene, all, c) || triangleCount(scene, scene.instances[c]) > maxTriangles) continue;
        const std::vector<WorldTriangle> shell = worldTriangles(scene, scene.instances[c], maxTriangles);
        const std::vector<glm::dvec3> samples = surfaceSamples(scene, c, 256);
        if (shell.empty() || samples.empty()) continue;
        bool blocksAll = true;
        for (const glm::dvec3& dir : skyDirections(scene)) {
            for (const glm::dvec3& p : samples) {
                const bool hit = std::any_of(shell.begin(), shell.end(),
                                             [&](const WorldTriangle& t) { return rayHits(t, p, dir, 1e-7 * scale); });
                if (!hit) {
                    blocksAll = false;
                    break;
                }
            }
            if (!blocksAll) break;
        }
        if (blocksAll) found.push_back(c);
    }
    return found;
}

Aabb castingBounds(const Scene& scene, const CasterModel& model) {
    if (model.instanceCasts.empty()) return scene.bounds;
    Aabb bounds;
    for (std::size_t i = 0; i < scene.instances.size(); ++i)
        if (model.instanceCastsShadow(i)) bounds.extend(scene.instances[i].worldBounds);
    return bounds.empty() ? scene.bounds : bounds;
}

std::size_t keepCasting(const CasterModel& model, std::vector<std::uint32_t>& instances) {
    if (model.instanceCasts.empty()) return 0;
    const std::size_t before = instances.size();
    std::erase_if(instances, [&](std::uint32_t i) { return !model.instanceCastsShadow(i); });
    return before - instances.size();
}

std::string casterFacesText(const CasterModel& model) {
    auto name = [](CasterFaces f) {
        return f == CasterFaces::Front ? "front" : f == CasterFaces::Back ? "back" : f == CasterFaces::Both ? "both" : "auto";
    };
    return std::string("single-sided ") + name(model.singleSided) + ", double-sided " + name(model.doubleSided);
}

bool namePatternMatches(std::string_view pattern, std::string_view name) {
    // Iterative glob with one backtrack point for the last '*'.
    std::size_t p = 0, n = 0, star = std::string_view::npos, resume = 0;
    while (n < name.size()) {
        if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
            ++p, ++n;
        } else if (p < pattern.size() && pattern[p] == '*') {
            star = p++;
            resume = n;
        } else if (star != std::string_view::npos) {
            p = star + 1;
            n = ++resume;
        } else {
            return false;
        }
    }
    while (p < pattern.size() && pattern[p] == '*') ++p;
    return p == pattern.size();
}

std::size_t pickInstance(const Scene& scene, const glm::dvec3& origin, const glm::dvec3& dir) {
    std::size_t best = SIZE_MAX;
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        double enter = 0.0;
        if (!rayEntersBox(scene.instances[i].worldBounds, origin, dir, nearest, enter)) continue;
        for (const WorldTriangle& t : worldTriangles(scene, scene.instances[i], SIZE_MAX)) {
            const double d = rayDistance(t, origin, dir);
            if (d < nearest) nearest = d, best = i;
        }
    }
    return best;
}

std::string toggleCasting(const Scene& scene, std::size_t instance, const std::vector<std::size_t>& backdrops,
                          CasterSettings& settings) {
    if (instance >= scene.instances.size()) return "nothing there to pick";
    const MeshInstance& inst = scene.instances[instance];
    std::string name =
        inst.node >= 0 && inst.node < int(scene.nodes.size()) ? scene.nodes[std::size_t(inst.node)].name : "";
    if (name.empty() && inst.mesh >= 0 && inst.mesh < int(scene.meshes.size()))
        name = scene.meshes[std::size_t(inst.mesh)].name;
    const std::string label = instanceLabel(scene, instance);
    if (name.empty()) return label + " has no name to switch its casting by";
    auto erase = [&](std::vector<std::string>& list) { std::erase(list, name); };
    if (chooseCasters(scene, settings, backdrops).model.instanceCastsShadow(instance)) {
        erase(settings.include);
        settings.exclude.push_back(name);
        return label + " casts no shadow now (casters.exclude += " + name + ")";
    }
    erase(settings.exclude);
    if (!chooseCasters(scene, settings, backdrops).model.instanceCastsShadow(instance))
        settings.include.push_back(name);
    return label + " casts shadows now";
}

std::string instanceLabel(const Scene& scene, std::size_t instance) {
    if (instance >= scene.instances.size()) return "instance " + std::to_string(instance);
    const MeshInstance& inst = scene.instances[instance];
    const std::string node =
        inst.node >= 0 && inst.node < int(scene.nodes.size()) ? scene.nodes[std::size_t(inst.node)].name : "";
    const std::string mesh =
        inst.mesh >= 0 && inst.mesh < int(scene.meshes.size()) ? scene.meshes[std::size_t(inst.mesh)].name : "";
    std::string label = node.empty() ? "node #" + std::to_string(inst.node) : "node '" + node + "'";
    if (!mesh.empty()) label += " (mesh '" + mesh + "')";
    return label;
}

CasterChoice chooseCasters(const Scene& scene, const CasterSettings& settings,
                           const std::vector<std::size_t>& backdrops) {
    CasterChoice choice;
    choice.model.singleSided = resolvedFaces(settings.singleSided);
    choice.model.doubleSided = resolvedFaces(settings.doubleSided);
    choice.backdrops = backdrops;
    if (settings.exclude.empty() && (backdrops.empty() || !settings.detectBackdrops)) return choice;

    auto matchesAny = [&](const std::vector<std::string>& patterns, std::size_t i) {
        const MeshInstance& inst = scene.instances[i];
        const std::string* node = inst.node >= 0 && inst.node < int(scene.nodes.size())
                                      ? &scene.nodes[std::size_t(inst.node)].name : nullptr;
        const std::string* mesh = inst.mesh >= 0 && inst.mesh < int(scene.meshes.size())
                                      ? &scene.meshes[std::size_t(inst.mesh)].name : nullptr;
        for (const std::string& p : patterns)
            if ((node && namePatternMatches(p, *node)) || (mesh && namePatternMatches(p, *mesh))) return true;
        return false;
    };
    choice.model.instanceCasts.assign(scene.instances.size(), 1);
    std::size_t byName = 0;
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        if (!settings.include.empty() && matchesAny(settings.include, i)) continue;
        if (!settings.exclude.empty() && matchesAny(settings.exclude, i)) {
            choice.model.instanceCasts[i] = 0;
            ++byName;
        }
    }
    if (byName > 0)
        choice.notices.push_back(std::to_string(byName) + " instance(s) cast no shadow: casters.exclude");
    for (std::size_t b : backdrops) {
        if (b >= scene.instances.size()) continue;
        const std::string label = instanceLabel(scene, b);
        if (!settings.detectBackdrops || (!settings.include.empty() && matchesAny(settings.include, b))) continue;
        if (choice.model.instanceCasts[b] == 0) continue;  // excluded by name already
        choice.model.instanceCasts[b] = 0;
        choice.notices.push_back(label + " is a backdrop (a closed shell around the scene that would shadow it all): "
                                 "it casts no shadow. To cast it: --set casters.include=NAME, or "
                                 "casters.detectBackdrops=false");
    }
    return choice;
}

}  // namespace shadowlab
