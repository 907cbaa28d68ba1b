#pragma once
// GPU resources of the shadow pipeline, (re)allocated only when their size changes and only when
// used: the shadow map, and the eye-space shadow-term textures of the blur (none when N = 0).
#include "gl/gl_objects.h"
#include "math/shadow_setup.h"

#include <cstdint>
#include <vector>

namespace shadowlab {

// Everything the content of the shadow map depends on. When this frame's key equals the key the
// map was rendered with, the map is reused (skip.reuseShadowMap). The light, the camera (every
// method here orients or focuses the map by the view, even unfocused SSM) and the method's
// parameters enter through the warp matrix and the linear-depth range; the casters through the
// culled caster set and when one of them last moved or deformed (animation): a moving non-caster
// leaves the map valid. Lookup-only settings (PCF kernel, constant
// offset, blur, view mode, overlays) are not part of it.
struct ShadowMapKey {
    const void* scene = nullptr;
    std::uint64_t sceneVersion = 0;  // bumped by every upload of geometry or materials
    std::uint64_t castersMoved = 0;  // the latest instance update that moved (or deformed) a caster
    int size = 0;
    glm::dmat4 worldToShadowClip{1.0};
    bool reversedDepth = false;
    bool linearDepth = false;
    LinearShadowDepth linear;
    bool mirrored = false;  // winding flip of the warp
    int offsetMode = 0;     // DepthOffset: slope-scale offsets are rendered into the map
    double slopeFactor = 0.0, slopeUnits = 0.0;
    int singleSidedFaces = 0, doubleSidedFaces = 0;  // CasterFaces the pass rasterises
    std::vector<std::uint32_t> casters;
    bool operator==(const ShadowMapKey& o) const;
};

// A depth-compare sampler, clamped to the edge: nearest or linear (hardware 2x2 PCF), the compare
// passing where reference <= stored (>= when `reversed`).
gl::SamplerObject createCompareSampler(bool linear, bool reversed);

// A square 32-bit float depth texture and its framebuffer, with two sampler objects for the lookup:
// compare + nearest and compare + linear (hardware 2x2 PCF). The compare direction follows the
// depth test of the pass that wrote it.
class ShadowMap {
public:
    void ensure(int size);
    int size() const { return size_; }
    GLuint framebuffer() const { return framebuffer_.id(); }
    GLuint texture() const { return depth_.id(); }
    GLuint sampler(bool linear, bool reversed) const;

    // Reuse bookkeeping: the key of the current content (none after a reallocation).
    bool holds(const ShadowMapKey& key) const { return hasContent_ && key == content_; }
    void setContent(ShadowMapKey key) { content_ = std::move(key), hasContent_ = true; }

private:
    ShadowMapKey content_;
    bool hasContent_ = false;
    int size_ = 0;
    gl::Texture depth_;
    gl::Framebuffer framebuffer_;
    gl::SamplerObject samplers_[2][2];  // [linear][reversed]
};

// Screen-sized targets of the eye-space blur: the shadow term (R8) with its depth, and a
// ping-pong partner for the separable passes.
class ShadowTermTargets {
public:
    void ensure(int width, int height);
    void release();
    bool allocated() const { return bool(term_[0]); }
    GLuint framebuffer(int i) const { return framebuffer_[i].id(); }
    GLuint term(int i) const { return term_[i].id(); }
    GLuint depth() const { return depth_.id(); }
    GLuint linearClampSampler() const { return sampler_.id(); }

private:
    int width_ = 0, height_ = 0;
    gl::Texture term_[2];
    gl::Texture depth_;
    gl::Framebuffer framebuffer_[2];
    gl::SamplerObject sampler_;
};

}  // namespace shadowlab
