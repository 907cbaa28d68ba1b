#pragma once
// Axis-aligned bounding box in double precision: scene bounds feed the shadow math, which
// must survive world offsets of 1e5 and far/near ratios of 1e6 (see stress suite).
#include <glm/glm.hpp>

#include <limits>

namespace shadowlab {

struct Aabb {
    glm::dvec3 min{std::numeric_limits<double>::infinity()};
    glm::dvec3 max{-std::numeric_limits<double>::infinity()};

    // Empty until a point is added; `!(min <= max)` also catches NaN.
    bool empty() const { return !(min.x <= max.x && min.y <= max.y && min.z <= max.z); }
    void extend(const glm::dvec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void extend(const Aabb& b) {
        if (b.empty()) return;
        extend(b.min);
        extend(b.max);
    }
    glm::dvec3 center() const { return 0.5 * (min + max); }
    glm::dvec3 extent() const { return max - min; }
    glm::dvec3 corner(int i) const {
        return {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z};
    }
    // Bounds of the box after an affine transform (the 8 corners, exact for boxes).
    Aabb transformed(const glm::dmat4& m) const {
        Aabb out;
        if (empty()) return out;
        for (int i = 0; i < 8; ++i) out.extend(glm::dvec3(m * glm::dvec4(corner(i), 1.0)));
        return out;
    }
    bool operator==(const Aabb&) const = default;
};

}  // namespace shadowlab
