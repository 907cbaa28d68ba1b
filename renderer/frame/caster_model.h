#pragma once
// Which triangles cast shadows: one definition that the shadow pass (one map and every cascade
// layer), caster culling and the ray-cast truth all read, so the map and the instrument that
// judges it cannot disagree about what a caster is. GL-free.
//
// A triangle casts when (1) its instance casts (not excluded by name, not a detected backdrop,
// or named in casters.include) and (2) the faces setting of its material's kind (single- or
// double-sided) lets the light see the side it shows the light. The side is the glTF front
// (counter-clockwise winding, clockwise under a node with det < 0: glTF 2.0 spec 3.7.4) when the
// front's normal points toward the light.
#include "scenes/scene.h"
#include "settings/settings.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab {

// Auto resolved for a material kind: never returns Auto.
CasterFaces resolvedFaces(CasterFaces setting);

struct CasterModel {
    CasterFaces singleSided = CasterFaces::Both;  // resolved (never Auto)
    CasterFaces doubleSided = CasterFaces::Both;
    std::vector<std::uint8_t> instanceCasts;  // per Scene::instances; empty: every instance casts

    CasterFaces faces(bool doubleSidedMaterial) const { return doubleSidedMaterial ? doubleSided : singleSided; }
    bool instanceCastsShadow(std::size_t instance) const {
        return instanceCasts.empty() || (instance < instanceCasts.size() && instanceCasts[instance] != 0);
    }
    // The rule both the rasteriser's face culling and the truth's ray filter implement.
    bool triangleCasts(bool doubleSidedMaterial, bool frontFacesLight) const {
        const CasterFaces f = faces(doubleSidedMaterial);
        return f == CasterFaces::Both || (f == CasterFaces::Front) == frontFacesLight;
    }
    bool operator==(const CasterModel&) const = default;
};

// Which instances cast, and why not: the notices the viewer shows and info/render print.
struct CasterChoice {
    CasterModel model;
    std::vector<std::size_t> backdrops;  // detected, whether excluded or kept by casters.include
    std::vector<std::string> notices;
};

// A backdrop: an instance whose world bounds hold every other instance's, and whose triangles
// (either side) block every ray from sample points on the other instances' surfaces toward each
// of a fixed set of sky directions (the upper hemisphere, +Y up, and straight up). A sky box or
// dome blocks them all; a room with a window lets some through; a ground plane lets all through.
// `maxTriangles` bounds the work per candidate (larger shells are not tested).
std::vector<std::size_t> detectBackdrops(const Scene& scene, std::size_t maxTriangles = 200000);

// The model for `settings` on `scene`, given the backdrops detectBackdrops found (computed once per
// scene by the caller, since it costs rays).
CasterChoice chooseCasters(const Scene& scene, const CasterSettings& settings,
                           const std::vector<std::size_t>& backdrops);

// The world bounds the shadow setup fits to: every instance's but those that cast nothing, so a
// sky box around the scene does not spread the map over empty sky (the scene's bounds when every
// instance casts).
Aabb castingBounds(const Scene& scene, const CasterModel& model);

// Removes from a caster list the instances the model keeps from casting; how many it removed.
std::size_t keepCasting(const CasterModel& model, std::vector<std::uint32_t>& instances);

// "single-sided both, double-sided both" (the --stats line and the viewer's stats).
std::string casterFacesText(const CasterModel& model);

// "node 'SkyBox' (mesh 'Cube')", as notices and the viewer's picker name an instance.
std::string instanceLabel(const Scene& scene, std::size_t instance);

// The viewer's picker: the instance whose triangle (either side) a ray from `origin` along `dir`
// hits first; SIZE_MAX when none.
std::size_t pickInstance(const Scene& scene, const glm::dvec3& origin, const glm::dvec3& dir);

// Switches one instance's casting in `settings` by its node name (its mesh's when the node has
// none): a casting instance goes into `exclude`; a non-casting one out of `exclude`, and into
// `include` when it is still kept out (a backdrop). What was done, in words.
std::string toggleCasting(const Scene& scene, std::size_t instance, const std::vector<std::size_t>& backdrops,
                          CasterSettings& settings);

// Glob match with * and ? (case-sensitive), as casters.exclude / include use.
bool namePatternMatches(std::string_view pattern, std::string_view name);

}  // namespace shadowlab
