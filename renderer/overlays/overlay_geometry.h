#pragma once
// What the overlays draw, as plain geometry (GL-free, unit-tested): the wireframes of the bodies
// of the shadow setup, coloured as the thesis figures colour them (Fig. 4.2: V blue, S green,
// B violet; Fig. 8.1: P red, light rays orange), and the third-person observer camera that looks
// at them (Figs. 4.2, 8.1, 9.1).
#include "math/cascades.h"
#include "math/shadow_setup.h"
#include "settings/settings.h"

#include <glm/glm.hpp>

#include <vector>

namespace shadowlab {

struct WireSet {
    glm::vec4 color{1.0f};
    std::vector<glm::dvec3> segments;  // pairs of end points (world)
};

// Edge segments of every polygon of a face list.
void appendPolygonEdges(const PolygonList& faces, std::vector<glm::dvec3>& segments);

// The wireframes the overlay settings ask for. V and S fall back to the camera frustum and the
// scene bounds when the diagnostics carry no polygons (no shadow this frame). `markerSize` is the
// arm length of the cross marking the projection centre; `lightDirection` (the way light travels)
// adds a few orange rays through B.
std::vector<WireSet> overlayWires(const ShadowDiagnostics& diagnostics, const OverlaySettings& overlays,
                                  const ViewFrustum& view, const Aabb& sceneBounds, const glm::dvec3& lightDirection,
                                  double markerSize);

// The colour of cascade split i, the tint of csm.colorSplits (shaders/cascade.glsl): red, green,
// blue, yellow from near to far; splits beyond the fourth repeat them.
glm::vec4 cascadeColor(int split);

// Cascaded shadow maps: for every split its slice of the view frustum (overlays.drawV,
// drawn darker) and its B_i (overlays.drawB), in the split's colour. Splits without a valid setup
// draw their slice only. `view` is the whole view frustum the splits divide.
std::vector<WireSet> cascadeWires(const CascadeSetup& cascades, const OverlaySettings& overlays,
                                  const ViewFrustum& view);

// Diagnostics for framing the observer on all splits: the first valid split's, with bodyB the
// faces of every B_i together (so the framing covers the far splits too). Empty diagnostics
// when no split is valid.
ShadowDiagnostics cascadeFramingDiagnostics(const CascadeSetup& cascades);

// A look-at + perspective camera standing outside the view frustum and B, looking at both.
struct ObserverCamera {
    glm::dvec3 eye{0.0};
    glm::dvec3 target{0.0};
    glm::dmat4 view{1.0};
    glm::dmat4 projection{1.0};
    double radius = 1.0;  // radius of the framed points around target
    glm::dmat4 viewProjection() const { return projection * view; }
};
// yawDeg turns around the target starting behind the camera (0 = looking over its shoulder),
// pitchDeg lifts the observer, distance scales the framing distance (1 = everything just fits).
// Frames B, the eye and the part of V inside S (a far plane may be huge), else all of V, and the
// projection centre when it is not much farther away than those.
ObserverCamera observerCamera(const ShadowDiagnostics& diagnostics, const ViewFrustum& view, const Aabb& sceneBounds,
                              double yawDeg, double pitchDeg, double distance, double aspect);

}  // namespace shadowlab
