#include "resources/cascade_maps.h"

#include <stdexcept>
#include <string>

namespace shadowlab {

void CascadeMaps::ensure(int size, int layers) {
    if (size == size_ && layers == layers_) return;
    depth_ = gl::createTexture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(depth_.id(), 1, GL_DEPTH_COMPONENT32F, size, size, layers);
    framebuffers_.clear();
    for (int layer = 0; layer < layers; ++layer) {
        gl::Framebuffer fb = gl::createFramebuffer();
        glNamedFramebufferTextureLayer(fb.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0, layer);
        glNamedFramebufferDrawBuffer(fb.id(), GL_NONE);
        glNamedFramebufferReadBuffer(fb.id(), GL_NONE);
        if (glCheckNamedFramebufferStatus(fb.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw std::runtime_error("cascade layer " + std::to_string(layer) + " (" + std::to_string(size) +
                                     "^2) is incomplete");
        framebuffers_.push_back(std::move(fb));
    }
    for (int linear = 0; linear < 2; ++linear)
        if (!samplers_[linear]) samplers_[linear] = createCompareSampler(linear, /*reversed=*/false);
    size_ = size;
    layers_ = layers;
    content_.assign(std::size_t(layers), ShadowMapKey{});
    hasContent_.assign(std::size_t(layers), false);
}

bool CascadeMaps::holds(int layer, const ShadowMapKey& key) const {
    const std::size_t i = std::size_t(layer);
    return layer >= 0 && i < hasContent_.size() && hasContent_[i] && content_[i] == key;
}

void CascadeMaps::setContent(int layer, ShadowMapKey key) {
    const std::size_t i = std::size_t(layer);
    if (layer < 0 || i >= content_.size()) return;
    content_[i] = std::move(key);
    hasContent_[i] = true;
}

void CascadeMaps::release() {
    depth_ = {};
    framebuffers_.clear();
    content_.clear();
    hasContent_.clear();
    size_ = layers_ = 0;
}

}  // namespace shadowlab
