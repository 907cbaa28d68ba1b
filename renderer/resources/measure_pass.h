#pragma once
// Float render targets of the measurement pass: three RGBA32F colour attachments (footprints +
// depth + shadow term; world position + receiver flag; normal + surface flag) and a depth buffer,
// (re)allocated only when the size changes. The pass itself is Renderer::measurePass
// (renderer/passes/renderer_measure.cpp); it runs when Renderer::renderMeasured asks for it.
#include "gl/gl_objects.h"
#include "measure/measure_frame.h"

namespace shadowlab {

class MeasureTargets {
public:
    void ensure(int width, int height);
    int width() const { return width_; }
    int height() const { return height_; }
    GLuint framebuffer() const { return framebuffer_.id(); }
    // Reads every attachment back into a MeasureFrame (rows bottom-up); the view fields stay unset.
    MeasureFrame read() const;

private:
    int width_ = 0, height_ = 0;
    gl::Texture colour_[3];
    gl::Renderbuffer depth_;
    gl::Framebuffer framebuffer_;
};

}  // namespace shadowlab
