#pragma once
// Light space (thesis 9.2.3): the frame every focused parameterization (SSM, LiSPSM) is built in.
// Light rays are parallel to light-space y (the light at y = +infinity); the frame's "up" vector
// (view direction or body vector) projected on the shadow plane is -z, so the map's image y runs
// along the view.
#include "math/shadow_internal.h"

namespace shadowlab::detail {

struct LightSpace {
    glm::dmat4 L{1.0};  // world -> light space: L = L_r L_p L_v^-1 (projective for spot lights)
    glm::dvec3 up{0.0};  // the frame's up vector (view direction or body vector)
    bool spot = false;
};

// e_world (thesis 9.2.3): the vertices of L n V n S nearest to the eye, averaged over those within
// a small distance of the nearest.
glm::dvec3 nearestVisiblePoint(const std::vector<glm::dvec3>& lvsVertices, const ViewFrustum& view, const ViewBasis& basis);

LightSpace makeLightSpace(const ShadowLight& light, const glm::dvec3& l, const glm::dvec3& up, const SpotFrustum& spot,
                          const glm::dvec3& eWorld, const glm::dvec3& viewDir, double rayLength,
                          const glm::dvec3& eyeOrigin);

struct LightSpaceExtent {
    Range x, y, z;
};
LightSpaceExtent extentIn(const glm::dmat4& L, const std::vector<glm::dvec3>& pts);

}  // namespace shadowlab::detail
