#pragma once
// Everything one frame's passes share, built once per Renderer::render. Private to the renderer's
// own files (renderer.cpp and the pass files beside it).
#include "math/cascades.h"
#include "frame/caster_model.h"
#include "renderer.h"

namespace shadowlab {

struct Renderer::Frame {
    const Scene& scene;
    const Settings& settings;
    Viewport viewport;
    ViewFrustum view;
    glm::dmat4 viewProjection;
    // The camera the shadows are set up for (pre-pass, B, warp, splits): `view`, unless
    // renderMeasured was handed another (the temporal instrument's map-only comparison).
    ViewFrustum shadowView;
    LightFrame light;
    bool shadowed = false;  // a shadow map is rendered and looked up this frame
    ShadowSetup shadow;
    glm::dmat4 worldToShadowClip{1.0};
    bool linearDepth = false;
    bool reversedDepth = false;
    LinearShadowDepth linear;
    InstanceList casters;
    InstanceList visible;  // view-frustum culling of the shadow-term and forward passes
    bool shadowMapMirrored = false;  // the warp flips the winding of light-facing triangles
    // Cascaded shadow maps (settings.csm): `shadow` is then split 0's setup (for overlays and
    // diagnostics); each split has its setup and its own culled casters.
    bool cascaded = false;
    CascadeSetup cascades{};
    std::vector<InstanceList> cascadeCasters{};
    CasterModel casterModel{};  // which triangles cast (frame/caster_model.h), for every map and the truth
    Aabb shadowBounds{};        // castingBounds: what the shadow setups fit to
};

}  // namespace shadowlab
