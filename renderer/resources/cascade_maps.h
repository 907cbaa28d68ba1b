#pragma once
// The depth texture array of cascaded shadow maps (math/cascades.h): one square 32-bit float
// layer per split, a framebuffer per layer, and compare samplers (nearest / hardware 2x2 PCF).
// Allocated on first use and when size or layer count changes; released when cascades are off.
#include "gl/gl_objects.h"
#include "resources/shadow_resources.h"

#include <vector>

namespace shadowlab {

class CascadeMaps {
public:
    void ensure(int size, int layers);
    void release();
    int size() const { return size_; }
    int layers() const { return layers_; }
    GLuint texture() const { return depth_.id(); }
    GLuint framebuffer(int layer) const { return framebuffers_[std::size_t(layer)].id(); }
    GLuint sampler(bool linear) const { return samplers_[linear ? 1 : 0].id(); }

    // Reuse bookkeeping per layer (skip.reuseShadowMap): the key each layer was rendered with
    // (none after a reallocation), so a layer whose split did not change is not drawn again.
    bool holds(int layer, const ShadowMapKey& key) const;
    void setContent(int layer, ShadowMapKey key);

private:
    int size_ = 0, layers_ = 0;
    std::vector<ShadowMapKey> content_;
    std::vector<bool> hasContent_;
    gl::Texture depth_;
    std::vector<gl::Framebuffer> framebuffers_;
    gl::SamplerObject samplers_[2];  // [linear]
};

}  // namespace shadowlab
