#include "resources/render_target.h"

#include <cstring>
#include <stdexcept>

namespace shadowlab {

RenderTarget::RenderTarget(int width, int height) : width_(width), height_(height) {
    framebuffer_ = gl::createFramebuffer();
    color_ = gl::createRenderbuffer();
    depth_ = gl::createRenderbuffer();
    glNamedRenderbufferStorage(color_.id(), GL_SRGB8_ALPHA8, width, height);
    glNamedRenderbufferStorage(depth_.id(), GL_DEPTH_COMPONENT32F, width, height);
    glNamedFramebufferRenderbuffer(framebuffer_.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_.id());
    glNamedFramebufferRenderbuffer(framebuffer_.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
    if (glCheckNamedFramebufferStatus(framebuffer_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("offscreen framebuffer " + std::to_string(width) + "x" + std::to_string(height) +
                                 " is incomplete");
}

RgbaImage RenderTarget::readColor() const { return readFramebuffer(framebuffer_.id(), 0, 0, width_, height_); }

RgbaImage readFramebuffer(GLuint framebuffer, int x, int y, int width, int height) {
    RgbaImage image;
    image.width = width;
    image.height = height;
    image.pixels.resize(std::size_t(width) * height * 4);
    std::vector<std::uint8_t> bottomUp(image.pixels.size());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(x, y, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    const std::size_t rowBytes = std::size_t(width) * 4;
    for (int row = 0; row < height; ++row)
        std::memcpy(&image.pixels[row * rowBytes], &bottomUp[(height - 1 - row) * rowBytes], rowBytes);
    return image;
}

}  // namespace shadowlab
