#pragma once
// The shadow math core's public API: one call per light per frame computes the intersection body
// B (thesis eq. 4.2), the world -> shadow-clip matrix of the chosen parameterization (SSM, PSM,
// LiSPSM) and the diagnostics the UI shows. Pure GLM, double precision, no GL.
//
// Conventions (all GL):
// - World space is right-handed; view space looks down -z; NDC z in [-1, 1].
// - worldToShadowClip maps every vertex of B into the clip cube: -w <= x, y, z <= w with w > 0
//   (checked by the tests and the stress suite with a 1e-4 tolerance on x/w, y/w, z/w).
//   Texture coordinates are 0.5 * ndc + 0.5; the caller applies that bias.
// - Depth test: with reverseDepthTest == false the shadow pass uses GL_LESS (clear to 1) and a
//   receiver is lit when its depth <= stored depth (+ bias). With reverseDepthTest == true (PSM
//   with an inverted post-perspective light, Stamminger & Drettakis section 3.1: the light rays
//   converge, so the occluder is the hit FARTHEST from the converging point) the shadow pass uses
//   GL_GREATER (clear to 0) and a receiver is lit when its depth >= stored depth (- bias).
//   Equivalently: the "effective depth" (reverseDepthTest ? -z_ndc : z_ndc) always grows along
//   the light's travel through B.
// - Linear depth (TSM idea, thesis ch. 5): see LinearShadowDepth below; it always grows along the
//   light's travel, so it never needs the reversed test.
#include "math/aabb.h"
#include "math/convex_body.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace shadowlab {

enum class ShadowMethod { SsmFocused, SsmUnfocused, Psm, Lispsm };

struct ViewFrustum {
    glm::dvec3 eye{0.0};
    glm::dvec3 forward{0.0, 0.0, -1.0};  // need not be unit; normalized internally
    glm::dvec3 up{0.0, 1.0, 0.0};        // any vector not parallel to forward (else a fallback up is used)
    double fovY = 1.0;                   // radians, full vertical angle
    double aspect = 1.0;                 // width / height
    double zNear = 0.1, zFar = 100.0;

    glm::dmat4 viewMatrix() const;        // world -> view (look-at)
    glm::dmat4 projectionMatrix() const;  // view -> clip, GL perspective, NDC z in [-1, 1]
};

enum class ShadowLightKind { Directional, Spot };

struct ShadowLight {
    ShadowLightKind kind = ShadowLightKind::Directional;
    glm::dvec3 direction{0.0, -1.0, 0.0};  // the way light travels (world); spot: the cone axis
    glm::dvec3 position{0.0};              // spot only
    double outerConeAngle = 0.5;           // spot only: half-angle, radians (clamped to [1e-3, 85 deg])
    double range = 0.0;                    // spot only: far distance; <= 0 means "up to the scene bounds"
};

// LiSPSM options. The warp is built from k = 1/n (thesis 9.2.4 with C at distance n = 1/k from
// P's near plane): k is computed in closed form from eq. 8.11 (directional) or 8.13 (spot) and is
// exactly 0 when sin(gamma) = 0 or z1/z0 <= 1, which *is* the focused SSM matrix in the same light
// frame. So LiSPSM -> SSM continuously as gamma -> 0, with no threshold and no blending weight:
// the rule is "k -> 0 linearly in sin(gamma)" (k = sin g / (z_n + sqrt(z_n (z_n + d sin g)))).
struct LispsmParams {
    bool useBodyVector = false;  // thesis 9.2.6 (directional lights only): frame up-vector from B
    double virtualFar = 0.0;     // thesis 9.2.5 / paper 4.4: z_f used for n only; <= 0 or >= zFar: real far
    // The nearest visible depth (the depth pre-pass measures it), used for n only, symmetric to
    // virtualFar: <= zNear means the real near plane.
    double pseudoNear = 0.0;
    bool overrideN = false;      // use `n` instead of n_opt
    double n = 1.0;
    // Where fewer than kEnoughMeasuredReceivers measured receivers face the light, the stand-ins
    // join them in the warp search (math/lispsm_search.h). A cascade split turns it off: its
    // receivers are few by construction and its warp is checked on the fine grid instead.
    bool standInsJoinFewReceivers = true;
};

// A visible surface point and its normal (unit), e.g. from the depth pre-pass.
struct SurfacePoint {
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0.0, 1.0, 0.0};
};

struct ShadowParams {
    ShadowMethod method = ShadowMethod::Lispsm;
    LispsmParams lispsm;
    // PSM: use the focused SSM where PSM's largest texel footprint over the visible receivers is
    // worse (diagnostics.fallback says so). Off: the bare parameterization (closed-form checks).
    bool psmGuard = true;
    // Visible surfaces with their normals (the depth pre-pass's coarse grid): where LiSPSM's warp
    // search and PSM's guard measure the footprint. Empty: the visible lit body's vertices stand in.
    std::vector<SurfacePoint> receiverPoints;
    // The pixel grid the depth pre-pass samples them at (and the method sweep simulates).
    static constexpr int kReceiverGridX = 8, kReceiverGridY = 6;
    // The same surfaces at a 4x finer grid, for a spot light that lights too small a part of the
    // image for the coarse grid (math/lispsm_search.h: receiversInLight). May be empty.
    std::vector<SurfacePoint> fineReceiverPoints;
    static constexpr int kFineReceiverGridX = 32, kFineReceiverGridY = 24;
    // LiSPSM's warp and PSM are kept only where their p95 and p99 footprint over the fine grid's
    // receivers are within 1.05x the uniform map's (math/image_check.h). Cascade splits check
    // their warps on the fine grid their own way (math/cascades.cpp).
    bool imageCheck = true;
    // Outward planes (n, d) that hold every visible receiver, e.g. the bounds of a cascade split's
    // depth pre-pass samples (math/cascades_sdsm.h): V n S is clipped by them before B is extruded
    // toward the light, so the map covers those receivers and their casters only. Empty: V n S.
    std::vector<glm::dvec4> receiverBounds;
    // PSM: the near plane pushed towards the nearest visible geometry (Stamminger & Drettakis 4.2,
    // 6); <= the view's own: none. Only PSM's own matrix is built with it: where the guard keeps
    // the focused SSM, that is the map of the view's own near plane, as the SSM method's (a spot
    // map's frame turns with the nearest visible point, and the pushed plane's SSM lost 1.52x on a
    // sweep view, seed 7).
    double psmNearPlane = 0.0;
    // Fill the polygon lists of ShadowDiagnostics (B, V, S, L, P). Scalars are always filled.
    bool collectPolygons = true;
};

// How the light looks in the camera's post-perspective space (Stamminger & Drettakis 3.1, 3.2).
// PSM recipe here: B's vertices go through a virtual camera moved back along -forward until all
// of B is in front of its near plane (4.2), with the near plane pushed to B's nearest depth and
// the far plane to B's farthest. The light, (-l, 0) or (position, 1), goes through the same
// matrix: w ~ 0 (farther than 1e4 radii of B') -> Directional (orthographic map along it);
// w > 0 -> Point; w < 0 -> InvertedPoint (rays converge: the hit farthest from the point is the
// occluder, so reverseDepthTest = true). The shadow frustum looks from the point at B' and is
// fitted around it. When the point sees B' only through a frustum wider than 80 degrees (a light
// close to the infinity plane with a huge far/near ratio), the camera moves back further, step
// by doubling step: the parameterization degrades continuously toward the uniform map (4.2).
enum class PostPerspectiveLight { None, Point, InvertedPoint, Directional };

struct ShadowDiagnostics {
    ShadowMethod method = ShadowMethod::Lispsm;
    bool focused = false;  // the map is fitted to B (everything but SsmUnfocused and some fallbacks)
    // World-space face loops (each a convex polygon, counter-clockwise seen from outside).
    PolygonList bodyB;    // the intersection body B = ((V n S) + l) n S n L   (thesis eq. 4.2)
    PolygonList viewV;    // the view frustum V
    PolygonList sceneS;   // the scene bounds S
    PolygonList lightL;   // spot lights: the light frustum L (a pyramid around the cone); else empty
    PolygonList lispsmP;  // LiSPSM: the perspective frustum P in world space; else empty
    glm::dvec3 projectionCenter{0.0};  // LiSPSM: C (world); PSM: the post-perspective light mapped back (if finite)
    bool hasProjectionCenter = false;
    // LiSPSM (thesis 9.2.5). n is the distance of C to P's near plane in light space; a value of
    // +infinity means "uniform" (P degenerates to the orthographic SSM fit). `warp` = 1 / nUsed is
    // what the matrix is built from, so the limit n -> infinity is exact and continuous.
    // nOptVirtual equals nOptReal when no virtual far plane is in effect (virtualFar <= zNear or
    // >= zFar). d, z0, z1 are those of the body n was computed from (the virtual one if used).
    double nUsed = 0.0, nOptReal = 0.0, nOptVirtual = 0.0, warp = 0.0;
    // Radians. Directional: angle between the frame's up vector (view direction or body vector)
    // and l. Spot: angle, in post-projective light space, between the orientation ray (9.2.3) and
    // the light rays.
    double gamma = 0.0;
    double d = 0.0;      // light-space z extent of B (thesis 9.2.4)
    // LiSPSM's measured warp choice (math/lispsm_search.h): the number of sample points, and the
    // largest texel footprint over them with SSM divided by that with the chosen warp (>= 1; 1
    // means the warp cannot beat the uniform map on this view and n = infinity was chosen).
    int warpSamples = 0;
    double estimatedGainOverSsm = 1.0;
    // The image check (math/image_check.h) of LiSPSM's searched warp or of PSM: the larger of its
    // p95 and p99 footprint over the pre-pass's fine grid divided by the uniform map's (0: not
    // checked; > 1.05: a weaker warp or the focused SSM was used), and the points it counted.
    double imageCheckLoss = 0.0;
    int imageCheckSamples = 0;
    double z0 = 0.0, z1 = 0.0;  // eye-space z (negative in front) of the points of eq. 8.13
    // PSM (Stamminger & Drettakis 4.2).
    double psmMoveBack = 0.0;   // how far the virtual camera moved back along -forward
    double psmNear = 0.0;       // the pushed near plane of the virtual camera (distance from it)
    double psmFar = 0.0;
    PostPerspectiveLight psmLightKind = PostPerspectiveLight::None;
    std::string fallback;  // empty if the method ran as designed; else what was done instead and why
};

// Linear light-space depth for a vertex shader (TSM, thesis ch. 5): write
//   t = radial ? length(p - origin) : dot(p - origin, axis);
//   depth01 = (t - nearDepth) / (farDepth - nearDepth);     // gl_Position.z = (2 * depth01 - 1) * w
// [nearDepth, farDepth] covers all of B, which already contains every caster that can shadow a
// visible point (B is extruded toward the light up to the scene bounds). It grows along the
// light's travel, so the ordinary GL_LESS test applies whatever the method.
// Directional: axis = l (unit), origin = eye. Spot: radial distance from the light position.
struct LinearShadowDepth {
    bool radial = false;
    glm::dvec3 origin{0.0};
    glm::dvec3 axis{0.0, -1.0, 0.0};
    double nearDepth = 0.0, farDepth = 1.0;
};

struct ShadowSetup {
    glm::dmat4 worldToShadowClip{1.0};  // what the shadow pass renders with (see conventions above)
    bool reverseDepthTest = false;      // GL_GREATER + clear to 0 + reversed compare (see above)
    LinearShadowDepth linearDepth;
    // Caster culling data (casterCanReach): B's outward planes and bounds.
    std::vector<glm::dvec4> bodyPlanes;
    Aabb bodyBounds;
    ShadowDiagnostics diagnostics;
    bool valid = false;  // false only when B is empty (nothing visible is lit): treat everything as lit
};

// Never throws; bad input (NaN, zero vectors, near >= far) gives valid == false with the reason in
// diagnostics.fallback. SSM (focused and unfocused) uses the same light frame as LiSPSM (the
// view direction projected onto the shadow plane points "up" in the map), so LiSPSM with n = inf
// is exactly SSM. SsmUnfocused fits the whole scene box (spot: S n L) instead of B.
// B is computed once per call; the cost is a few microseconds (see tests/bench).
ShadowSetup computeShadowSetup(const ViewFrustum& view, const ShadowLight& light, const Aabb& sceneBounds,
                               const ShadowParams& params);

// Can an object with these world bounds cast a shadow onto a visible, lit point? Every point that
// shadows a visible point lies in B (B = V n S extruded toward the light, clipped by S and L), so
// a box that is separated from B by one of B's planes (or by B's bounds) cannot. Conservative
// (a small relative tolerance keeps touching boxes). False when !setup.valid.
bool casterCanReach(const ShadowSetup& setup, const Aabb& casterBounds);

// --- Building blocks, public for tests and the UI ---------------------------------------------

// The spot light's frustum L: a square pyramid circumscribing the cone, apex at the light.
// nearPlane/farPlane are distances along the axis (far: range, or to the farthest corner of S;
// near: 1e-4 of far, at least 1e-7 of the light position's magnitude). B stops at the near plane;
// casterCanReach still keeps casters between the apex and it.
// Light space for spot lights (thesis 9.2.3): L = L_r L_p L_v^-1 with L_p a GL frustum along -y,
// so light rays become parallel to y there and the directional machinery applies.
struct SpotFrustum {
    glm::dmat4 view{1.0}, projection{1.0};
    double nearPlane = 0.0, farPlane = 0.0;
};
SpotFrustum spotFrustum(const ShadowLight& light, const Aabb& sceneBounds);

// The view frustum V as a body, built from its corners (more precise than inverting the
// view-projection for far/near ratios of 1e6).
ConvexBody frustumBody(const ViewFrustum& view);

// B = ((V n S) + l) n S n L (thesis eq. 4.2, 9.2.2), for V = `view` (any far plane, e.g. the
// virtual one). Empty when nothing visible is lit. `visibleLit`, when given, receives L n V n S
// (the body thesis 9.2.3 takes e_world from). `receiverBounds` (ShadowParams::receiverBounds)
// clip V n S before the extrusion.
ConvexBody intersectionBody(const ViewFrustum& view, const ShadowLight& light, const Aabb& sceneBounds,
                            ConvexBody* visibleLit = nullptr, const std::vector<glm::dvec4>& receiverBounds = {});

// n_opt for directional lights, thesis eq. 8.11; returns +infinity for sin(gamma) == 0.
double lispsmNOptDirectional(double zNear, double d, double sinGamma);
// n_opt from eye-space z values, thesis eq. 8.13 in the form consistent with eq. 8.11/8.12
// (n = d / (sqrt(z1/z0) - 1)); +infinity when z1/z0 <= 1.
double lispsmNOptGeneral(double d, double z0, double z1);

}  // namespace shadowlab
