#pragma once
// Where a ray enters an axis-aligned box (the slab test), for the CPU ray queries that pick and
// probe the scene (the viewer's ground probe, the caster model's object pick).
#include "math/aabb.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace shadowlab {

// The parameter at which origin + t dir, t in [0, tMax], enters `box` (0 when the origin is
// inside); false when it misses. Axes the ray runs parallel to only check the origin's slab.
inline bool rayEntersBox(const Aabb& box, const glm::dvec3& origin, const glm::dvec3& dir, double tMax, double& tEnter) {
    double t0 = 0.0, t1 = tMax;
    for (int a = 0; a < 3; ++a) {
        if (std::abs(dir[a]) < 1e-300) {
            if (origin[a] < box.min[a] || origin[a] > box.max[a]) return false;
            continue;
        }
        double near = (box.min[a] - origin[a]) / dir[a], far = (box.max[a] - origin[a]) / dir[a];
        if (near > far) std::swap(near, far);
        t0 = std::max(t0, near);
        t1 = std::min(t1, far);
        if (t0 > t1) return false;
    }
    tEnter = t0;
    return true;
}

}  // namespace shadowlab
