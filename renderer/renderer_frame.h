#pragma once
// Everything one frame's passes share, built once per Renderer::render. Private to the renderer's
// own files (renderer.cpp and the pass files beside it).
#include "renderer.h"

namespace shadowlab {

struct Renderer::Frame {
    const Scene& scene;
    const Settings& settings;
    Viewport viewport;
    ViewFrustum view;
    glm::dmat4 viewProjection;
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
};

}  // namespace shadowlab
