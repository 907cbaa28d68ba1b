#include "ground_probe.h"

#include "math/ray_box.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowlab::app {

namespace {

// Ray parameter of the hit of origin + t dir with triangle (a, b, c), both faces (Moller-Trumbore);
// negative for a miss.
double hitDistance(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& a, const glm::dvec3& b,
                   const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a, e2 = c - a;
    const glm::dvec3 p = glm::cross(dir, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-18) return -1.0;
    const double inv = 1.0 / det;
    const glm::dvec3 s = origin - a;
    const double u = glm::dot(s, p) * inv;
    if (u < 0.0 || u > 1.0) return -1.0;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(dir, q) * inv;
    if (v < 0.0 || u + v > 1.0) return -1.0;
    return glm::dot(e2, q) * inv;
}

// Below this many triangles a primitive is searched whole.
constexpr std::size_t kGridMinTriangles = 64;

GroundProbe::Grid buildGrid(const Primitive& prim) {
    GroundProbe::Grid grid;
    const std::size_t count = prim.triangleCount();
    if (count < kGridMinTriangles || prim.bounds.empty()) return grid;
    // About four triangles per cell for a height field.
    grid.cells = std::clamp(int(std::sqrt(double(count) / 4.0)), 1, 512);
    grid.min = {prim.bounds.min.x, prim.bounds.min.z};
    const glm::dvec2 extent(prim.bounds.max.x - prim.bounds.min.x, prim.bounds.max.z - prim.bounds.min.z);
    grid.cellSize = glm::max(extent / double(grid.cells), glm::dvec2(1e-9));
    auto cellRange = [&](std::size_t t, glm::ivec2& lo, glm::ivec2& hi) {
        glm::dvec2 mn(std::numeric_limits<double>::infinity()), mx(-std::numeric_limits<double>::infinity());
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t i = prim.indices[3 * t + std::size_t(k)];
            if (i >= prim.positions.size()) return false;
            const glm::dvec2 p(prim.positions[i].x, prim.positions[i].z);
            mn = glm::min(mn, p);
            mx = glm::max(mx, p);
        }
        lo = glm::clamp(glm::ivec2(glm::floor((mn - grid.min) / grid.cellSize)), 0, grid.cells - 1);
        hi = glm::clamp(glm::ivec2(glm::floor((mx - grid.min) / grid.cellSize)), 0, grid.cells - 1);
        return true;
    };
    const std::size_t cellCount = std::size_t(grid.cells) * std::size_t(grid.cells);
    grid.start.assign(cellCount + 1, 0);
    glm::ivec2 lo, hi;
    for (int pass = 0; pass < 2; ++pass) {  // count, then fill
        std::vector<std::uint32_t> next(grid.start.begin(), grid.start.end() - 1);
        if (pass == 1) grid.triangles.resize(grid.start.back());
        for (std::size_t t = 0; t < count; ++t) {
            if (!cellRange(t, lo, hi)) continue;
            for (int z = lo.y; z <= hi.y; ++z)
                for (int x = lo.x; x <= hi.x; ++x) {
                    const std::size_t c = std::size_t(z) * std::size_t(grid.cells) + std::size_t(x);
                    if (pass == 0) ++grid.start[c + 1];
                    else grid.triangles[next[c]++] = std::uint32_t(t);
                }
        }
        if (pass == 0)
            for (std::size_t c = 0; c < cellCount; ++c) grid.start[c + 1] += grid.start[c];
    }
    return grid;
}

// The nearest hit going down from (x, fromY, z) over the scene's triangles, with the primitives'
// grids where given (grids[mesh][primitive]).
std::optional<double> nearestBelow(const Scene& scene, const std::vector<std::vector<GroundProbe::Grid>>* grids,
                                   double x, double z, double fromY) {
    if (!std::isfinite(x) || !std::isfinite(z) || !std::isfinite(fromY)) return std::nullopt;
    double nearest = std::numeric_limits<double>::infinity();  // world distance down
    for (const MeshInstance& instance : scene.instances) {
        const Aabb& wb = instance.worldBounds;
        if (instance.mesh < 0 || std::size_t(instance.mesh) >= scene.meshes.size() || wb.empty()) continue;
        if (x < wb.min.x || x > wb.max.x || z < wb.min.z || z > wb.max.z || wb.min.y > fromY) continue;
        if (fromY - wb.max.y >= nearest) continue;
        // The ray in object space: an affine map keeps the ray parameter, so t stays the world
        // distance down (the world direction has length 1).
        const glm::dmat4 toObject = glm::inverse(instance.world);
        const glm::dvec3 origin = glm::dvec3(toObject * glm::dvec4(x, fromY, z, 1.0));
        const glm::dvec3 dir = glm::dvec3(toObject * glm::dvec4(0.0, -1.0, 0.0, 0.0));
        // Still vertical in object space (rotations about y, scales): the grid cell under it holds
        // every triangle it can meet.
        const bool vertical = std::abs(dir.x) + std::abs(dir.z) <= 1e-12 * std::abs(dir.y);
        const auto& prims = scene.meshes[std::size_t(instance.mesh)].primitives;
        for (std::size_t pi = 0; pi < prims.size(); ++pi) {
            const Primitive& prim = prims[pi];
            if (double enter = 0.0; !rayEntersBox(prim.bounds, origin, dir, nearest, enter)) continue;
            const auto& pos = prim.positions;
            auto test = [&](std::size_t t) {
                const std::uint32_t ia = prim.indices[3 * t], ib = prim.indices[3 * t + 1], ic = prim.indices[3 * t + 2];
                if (ia >= pos.size() || ib >= pos.size() || ic >= pos.size()) return;
                const double d = hitDistance(origin, dir, pos[ia], pos[ib], pos[ic]);
                if (d >= 0.0 && d < nearest) nearest = d;
            };
            // A mesh added after the index was built (the ground plane) has no grid.
            const bool indexed = grids && std::size_t(instance.mesh) < grids->size() &&
                                 pi < (*grids)[std::size_t(instance.mesh)].size();
            const GroundProbe::Grid* grid = indexed && vertical ? &(*grids)[std::size_t(instance.mesh)][pi] : nullptr;
            if (grid && grid->cells > 0) {
                const glm::ivec2 c = glm::clamp(glm::ivec2(glm::floor((glm::dvec2(origin.x, origin.z) - grid->min) /
                                                                      grid->cellSize)),
                                                0, grid->cells - 1);
                const std::size_t cell = std::size_t(c.y) * std::size_t(grid->cells) + std::size_t(c.x);
                for (std::uint32_t i = grid->start[cell]; i < grid->start[cell + 1]; ++i) test(grid->triangles[i]);
            } else {
                for (std::size_t t = 0; t < prim.triangleCount(); ++t) test(t);
            }
        }
    }
    if (!std::isfinite(nearest)) return std::nullopt;
    return fromY - nearest;
}

}  // namespace

std::optional<double> groundBelow(const Scene& scene, double x, double z, double fromY) {
    return nearestBelow(scene, nullptr, x, z, fromY);
}

GroundProbe::GroundProbe(const Scene& scene) : scene_(&scene) {
    grids_.resize(scene.meshes.size());
    for (std::size_t m = 0; m < scene.meshes.size(); ++m)
        for (const Primitive& prim : scene.meshes[m].primitives) grids_[m].push_back(buildGrid(prim));
}

std::optional<double> GroundProbe::below(double x, double z, double fromY) const {
    return nearestBelow(*scene_, &grids_, x, z, fromY);
}

glm::dvec3 walkTo(const GroundProbe& ground, const glm::dvec3& from, const glm::dvec3& to, double eyeHeight) {
    const double eye = std::max(eyeHeight, 1e-3);
    const glm::dvec2 start(from.x, from.z), end(to.x, to.z);
    const double length = glm::distance(start, end);
    // Bounded: a wild jump (a typed position) is walked in at most 256 probes.
    const int steps = std::clamp(int(std::ceil(length / (0.5 * eye))), 1, 256);
    const double step = length / steps;
    double foot = from.y - eye;
    for (int i = 1; i <= steps; ++i) {
        const glm::dvec2 p = glm::mix(start, end, double(i) / steps);
        if (const auto g = ground.below(p.x, p.y, foot + eye + 2.0 * step)) foot = *g;
    }
    return {to.x, foot + eye, to.z};
}

double defaultFlySpeed(const Scene& scene, const glm::dvec3& eye) {
    const double size = glm::length(scene.bounds.extent());
    double speed = std::isfinite(size) && size > 0.0 ? size * 0.1 : 5.0;
    if (const auto ground = groundBelow(scene, eye.x, eye.z, eye.y))
        speed = std::min(speed, 3.0 * std::max(0.5, eye.y - *ground));
    return std::max(speed, 0.05);
}

}  // namespace shadowlab::app
