#pragma once
// The ground under a point, for the viewer's walk mode and the default fly speed (GL-free): a ray
// straight down against the scene's triangles in world space. Instances whose world bounds miss
// the vertical line are skipped; GroundProbe also keeps a grid over each primitive's triangles
// (object-space x/z), so a walk step costs a few cells of the forest's 131k-triangle terrain
// instead of all of them.
#include "scenes/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace shadowlab::app {

// Height of the first surface a ray down from (x, fromY, z) meets; nullopt when it meets none.
// Both faces of a triangle count (a terrain seen from below is still the ground). Tests every
// triangle under the point: for one probe; GroundProbe for many.
std::optional<double> groundBelow(const Scene& scene, double x, double z, double fromY);

class GroundProbe {
public:
    // Indexes the scene's primitives; the scene must outlive the probe and keep its geometry.
    explicit GroundProbe(const Scene& scene);
    // As groundBelow.
    std::optional<double> below(double x, double z, double fromY) const;
    const Scene& scene() const { return *scene_; }

    // Triangles of one primitive by object-space x/z cell (CSR: cell c's triangles are
    // triangles[start[c] .. start[c + 1]]).
    struct Grid {
        glm::dvec2 min{0.0}, cellSize{1.0};
        int cells = 0;  // per side
        std::vector<std::uint32_t> start, triangles;
    };

private:
    const Scene* scene_;
    std::vector<std::vector<Grid>> grids_;  // per mesh, per primitive
};

// The eye moved from `from` to `to`'s horizontal position, kept `eyeHeight` above the ground. The
// way is walked in steps of at most half the eye height, each probing from the last foot height
// plus the eye height plus twice the step, so slopes up to ~75 deg are climbed instead of being
// passed under; where no ground is found (off the scene's edge) the foot height is kept.
glm::dvec3 walkTo(const GroundProbe& ground, const glm::dvec3& from, const glm::dvec3& to, double eyeHeight);

// The fly speed a camera at `eye` starts with: a tenth of the scene's diagonal per second, but
// at most three eye heights per second above the ground under it (a walker at 1.8 m: 5.4 m/s),
// the height taken as at least 0.5 m. The forest is 720 m across: 72 m/s crossed it in 10 s,
// and a tap at 1.6 s a frame flew 54 m with the eye 1.8 m over the ground.
double defaultFlySpeed(const Scene& scene, const glm::dvec3& eye);

}  // namespace shadowlab::app
