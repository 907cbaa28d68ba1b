#pragma once
// The texel footprint: how many screen pixels one shadow-map texel covers at a receiver point,
// m = max(|row of J|) / |det J| with J = d(texel) / d(pixel) on the receiver's tangent plane
// (equivalently the longer screen-space edge of one texel: the largest column norm of J^-1).
// m > 1 is undersampling (thesis 3.1: dp/ds > 1 shows the map's texels as blocks). This is the
// one error measure the LiSPSM n search, the PSM guard and the method sweep share, so a method
// that "wins" here wins on the same metric the sweep reports. Pure GLM, double precision.
#include <glm/glm.hpp>

namespace shadowlab {

struct FootprintCamera {
    glm::dmat4 viewProjection{1.0};  // world -> camera clip
    double widthPx = 1280.0, heightPx = 720.0;
};

// NaN when the point is behind the camera or the light (w <= 0); +infinity when the light grazes
// the receiver plane (a texel covers an unbounded strip of it).
double texelFootprint(const glm::dmat4& worldToShadowClip, double mapSize, const FootprintCamera& camera,
                      const glm::dvec3& point, const glm::dvec3& normal);

// d(ndc.xy)/d(world) of a projective map at p, scaled by `scale` (pixels or texels per NDC unit
// over 2). Rows: x and y. Returns false when w <= 0.
bool projectedGradient(const glm::dmat4& m, const glm::dvec3& p, glm::dvec2 scale, glm::dvec3& gx, glm::dvec3& gy);

// m from the gradients of texel (u, v) and pixel (x, y) coordinates, on the plane with tangents t1, t2.
double footprintFromGradients(const glm::dvec3& gu, const glm::dvec3& gv, const glm::dvec3& gx, const glm::dvec3& gy,
                              const glm::dvec3& t1, const glm::dvec3& t2);

}  // namespace shadowlab
