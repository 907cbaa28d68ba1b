#include "culling/cull_volume.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

CullVolume CullVolume::viewFrustum(const ClipPlanes& planes) {
    CullVolume v;
    v.planes_.assign(std::begin(planes.planes), std::end(planes.planes));
    return v;
}

CullVolume CullVolume::casterReach(const ShadowSetup& setup) {
    CullVolume v;
    if (!setup.valid || setup.bodyBounds.empty()) {
        v.empty_ = true;
        return v;
    }
    // B's face planes point outward: flip them. B's bounds are six more half-spaces.
    for (const glm::dvec4& p : setup.bodyPlanes) v.planes_.push_back(-p);
    const Aabb& b = setup.bodyBounds;
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec4 lo(0.0), hi(0.0);
        lo[axis] = 1.0;
        lo.w = -b.min[axis];
        hi[axis] = -1.0;
        hi.w = b.max[axis];
        v.planes_.push_back(lo);
        v.planes_.push_back(hi);
    }
    return v;
}

CullVolume CullVolume::inObjectSpace(const glm::dmat4& world) const {
    CullVolume v = *this;
    const glm::dmat4 t = glm::transpose(world);
    for (glm::dvec4& p : v.planes_) p = t * p;
    return v;
}

bool CullVolume::mayContain(const Aabb& box) const {
    if (empty_ || box.empty()) return false;
    for (const glm::dvec4& p : planes_) {
        // The box corner farthest along the plane normal (the "p-vertex").
        const glm::dvec3 far{p.x >= 0 ? box.max.x : box.min.x, p.y >= 0 ? box.max.y : box.min.y,
                             p.z >= 0 ? box.max.z : box.min.z};
        // A tolerance relative to the plane's own size (as casterCanReach's 1e-9) keeps boxes
        // touching it despite rounding; it does not depend on the box, so the test stays monotone.
        const double tol = 1e-9 * (std::abs(p.x) + std::abs(p.y) + std::abs(p.z) + std::abs(p.w));
        if (glm::dot(glm::dvec3(p), far) + p.w < -tol) return false;
    }
    return true;
}

}  // namespace shadowlab
