#pragma once
// An offscreen framebuffer (sRGB colour + 32-bit float depth) for headless rendering and screenshots.
#include "gl/gl_objects.h"
#include "image/image.h"

namespace shadowlab {

class RenderTarget {
public:
    RenderTarget(int width, int height);
    GLuint framebuffer() const { return framebuffer_.id(); }
    int width() const { return width_; }
    int height() const { return height_; }
    // Reads the sRGB-encoded colour back, top row first.
    RgbaImage readColor() const;

private:
    int width_, height_;
    gl::Framebuffer framebuffer_;
    gl::Renderbuffer color_;
    gl::Renderbuffer depth_;
};

// Reads a region of any framebuffer (0 = the window's), top row first.
RgbaImage readFramebuffer(GLuint framebuffer, int x, int y, int width, int height);

}  // namespace shadowlab
