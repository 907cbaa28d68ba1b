#pragma once
// Light space perspective shadow maps (Wimmer et al. 2004; thesis ch. 8 and 9.2.4-9.2.6): a
// perspective P along the view direction projected on the shadow plane, in light space.
#include "math/light_space.h"

namespace shadowlab::detail {

struct LispsmInputs {
    const ViewFrustum& view;
    const ViewBasis& basis;
    const ShadowLight& light;
    const Aabb& sceneBounds;
    const LightSpace& ls;
    const std::vector<glm::dvec3>& bodyVertices;  // B
    const ConvexBody& visibleLit;                 // L n V n S (V n S for suns): where receivers are
    const std::vector<glm::dvec3>& visibleLitVertices;
    const std::vector<SurfacePoint>& measuredReceivers;
    glm::dvec3 eWorld;                            // thesis 9.2.3
    double rayLength = 1.0;                       // a length of B's scale (for finite differences)
    // The pre-pass's fine grid, over which the searched warp is checked (math/image_check.h); null: no check.
    const std::vector<SurfacePoint>* imageReceivers = nullptr;
};

// The world -> shadow-clip matrix; fills the LiSPSM part of `diag` (n, gamma, d, z0, z1, C, P).
glm::dmat4 lispsmMatrix(const LispsmInputs& in, const LispsmParams& params, bool collectPolygons,
                        ShadowDiagnostics& diag);

// The focused uniform map (SSM) in the same light frame: LiSPSM's k = 0 limit (thesis 8.2.3).
glm::dmat4 uniformMatrix(const LightSpace& ls, const std::vector<glm::dvec3>& pts);

}  // namespace shadowlab::detail
