#include "resources/shadow_resources.h"

#include <stdexcept>
#include <string>

namespace shadowlab {

bool ShadowMapKey::operator==(const ShadowMapKey& o) const {
    const auto sameLinear = [](const LinearShadowDepth& a, const LinearShadowDepth& b) {
        return a.radial == b.radial && a.origin == b.origin && a.axis == b.axis && a.nearDepth == b.nearDepth &&
               a.farDepth == b.farDepth;
    };
    return scene == o.scene && sceneVersion == o.sceneVersion && castersMoved == o.castersMoved && size == o.size &&
           worldToShadowClip == o.worldToShadowClip && reversedDepth == o.reversedDepth &&
           linearDepth == o.linearDepth && (!linearDepth || sameLinear(linear, o.linear)) && mirrored == o.mirrored &&
           offsetMode == o.offsetMode && slopeFactor == o.slopeFactor && slopeUnits == o.slopeUnits &&
           singleSidedFaces == o.singleSidedFaces && doubleSidedFaces == o.doubleSidedFaces && casters == o.casters;
}

gl::SamplerObject createCompareSampler(bool linear, bool reversed) {
    gl::SamplerObject s = gl::createSampler();
    const GLint filter = linear ? GL_LINEAR : GL_NEAREST;
    glSamplerParameteri(s.id(), GL_TEXTURE_MIN_FILTER, filter);
    glSamplerParameteri(s.id(), GL_TEXTURE_MAG_FILTER, filter);
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_FUNC, reversed ? GL_GEQUAL : GL_LEQUAL);
    return s;
}

void ShadowMap::ensure(int size) {
    if (size == size_) return;
    hasContent_ = false;
    depth_ = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(depth_.id(), 1, GL_DEPTH_COMPONENT32F, size, size);
    framebuffer_ = gl::createFramebuffer();
    glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    glNamedFramebufferDrawBuffer(framebuffer_.id(), GL_NONE);
    glNamedFramebufferReadBuffer(framebuffer_.id(), GL_NONE);
    if (glCheckNamedFramebufferStatus(framebuffer_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("shadow map framebuffer " + std::to_string(size) + "^2 is incomplete");
    for (int linear = 0; linear < 2; ++linear)
        for (int reversed = 0; reversed < 2; ++reversed) {
            if (!samplers_[linear][reversed]) samplers_[linear][reversed] = createCompareSampler(linear, reversed);
        }
    size_ = size;
}

GLuint ShadowMap::sampler(bool linear, bool reversed) const { return samplers_[linear ? 1 : 0][reversed ? 1 : 0].id(); }

void ShadowTermTargets::ensure(int width, int height) {
    if (allocated() && width == width_ && height == height_) return;
    depth_ = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(depth_.id(), 1, GL_DEPTH_COMPONENT32F, width, height);
    for (int i = 0; i < 2; ++i) {
        term_[i] = gl::createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(term_[i].id(), 1, GL_RGBA8, width, height);  // term + normal
        framebuffer_[i] = gl::createFramebuffer();
        glNamedFramebufferTexture(framebuffer_[i].id(), GL_COLOR_ATTACHMENT0, term_[i].id(), 0);
        if (i == 0) glNamedFramebufferTexture(framebuffer_[i].id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
        if (glCheckNamedFramebufferStatus(framebuffer_[i].id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw std::runtime_error("shadow-term framebuffer is incomplete");
    }
    if (!sampler_) {
        sampler_ = gl::createSampler();
        glSamplerParameteri(sampler_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glSamplerParameteri(sampler_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glSamplerParameteri(sampler_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glSamplerParameteri(sampler_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    width_ = width;
    height_ = height;
}

void ShadowTermTargets::release() {
    for (int i = 0; i < 2; ++i) {
        term_[i].reset();
        framebuffer_[i].reset();
    }
    depth_.reset();
    width_ = height_ = 0;
}

}  // namespace shadowlab
