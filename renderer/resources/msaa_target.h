#pragma once
// The multisampled colour + depth target the forward pass draws into when anti-aliasing is on
// (Settings::display.msaaSamples > 1), resolved into the view's framebuffer afterwards.
#include "gl/gl_objects.h"

namespace shadowlab {

class MsaaTarget {
public:
    // (Re)allocates for a width x height view with `samples` (clamped to GL_MAX_SAMPLES).
    void ensure(int width, int height, int samples);
    GLuint framebuffer() const { return framebuffer_.id(); }
    int samples() const { return samples_; }
    // Averages the samples into `target` at (x, y), in linear space (sRGB decode/encode on).
    void resolveInto(GLuint target, int x, int y) const;
    void release();

private:
    int width_ = 0, height_ = 0, samples_ = 0;
    gl::Framebuffer framebuffer_;
    gl::Renderbuffer color_, depth_;
};

}  // namespace shadowlab
