#pragma once
// GPU resources of the shadow pipeline, (re)allocated only when their size changes and only when
// used: the shadow map, and the eye-space shadow-term textures of the blur (none when N = 0).
#include "gl/gl_objects.h"

namespace shadowlab {

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

private:
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
