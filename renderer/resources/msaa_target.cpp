#include "resources/msaa_target.h"

#include <algorithm>

namespace shadowlab {

void MsaaTarget::ensure(int width, int height, int samples) {
    GLint maxSamples = 1;
    glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
    samples = std::clamp(samples, 1, std::max(1, int(maxSamples)));
    if (width == width_ && height == height_ && samples == samples_ && framebuffer_.id() != 0) return;
    framebuffer_ = gl::createFramebuffer();
    color_ = gl::createRenderbuffer();
    depth_ = gl::createRenderbuffer();
    // sRGB storage like the window and the headless target: written encoded, resolved in linear.
    glNamedRenderbufferStorageMultisample(color_.id(), samples, GL_SRGB8_ALPHA8, width, height);
    glNamedRenderbufferStorageMultisample(depth_.id(), samples, GL_DEPTH_COMPONENT32F, width, height);
    glNamedFramebufferRenderbuffer(framebuffer_.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_.id());
    glNamedFramebufferRenderbuffer(framebuffer_.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
    width_ = width;
    height_ = height;
    samples_ = samples;
}

void MsaaTarget::resolveInto(GLuint target, int x, int y) const {
    glEnable(GL_FRAMEBUFFER_SRGB);
    glBlitNamedFramebuffer(framebuffer_.id(), target, 0, 0, width_, height_, x, y, x + width_, y + height_,
                           GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glDisable(GL_FRAMEBUFFER_SRGB);
}

void MsaaTarget::release() {
    framebuffer_ = gl::Framebuffer();
    color_ = gl::Renderbuffer();
    depth_ = gl::Renderbuffer();
    width_ = height_ = samples_ = 0;
}

}  // namespace shadowlab
