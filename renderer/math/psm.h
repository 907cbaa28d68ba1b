#pragma once
// Perspective shadow maps (Stamminger & Drettakis 2002): the map is rendered in the camera's
// post-perspective space. See PostPerspectiveLight in shadow_setup.h for the recipe.
#include "math/shadow_internal.h"

namespace shadowlab::detail {

struct PsmResult {
    bool ok = false;
    glm::dmat4 matrix{1.0};
    bool reverse = false;
    double moveBack = 0.0, extraMoveBack = 0.0, zNear = 0.0, zFar = 0.0;
    PostPerspectiveLight kind = PostPerspectiveLight::None;
    glm::dvec3 lightWorld{0.0};
    bool hasLightWorld = false;
};

// `bv`: the vertices of B. ok == false when no shadow frustum from the post-perspective light
// contains B' (the caller falls back to focused SSM).
PsmResult perspectiveShadowMap(const ViewFrustum& view, const ViewBasis& basis, const ShadowLight& light,
                               const glm::dvec3& l, const std::vector<glm::dvec3>& bv);

}  // namespace shadowlab::detail
