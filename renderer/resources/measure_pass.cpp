#include "resources/measure_pass.h"

#include <stdexcept>
#include <string>

namespace shadowlab {

void MeasureTargets::ensure(int width, int height) {
    if (width == width_ && height == height_ && framebuffer_) return;
    framebuffer_ = gl::createFramebuffer();
    const GLenum attachments[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    for (int i = 0; i < 3; ++i) {
        colour_[i] = gl::createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(colour_[i].id(), 1, GL_RGBA32F, width, height);
        glNamedFramebufferTexture(framebuffer_.id(), attachments[i], colour_[i].id(), 0);
    }
    depth_ = gl::createRenderbuffer();
    glNamedRenderbufferStorage(depth_.id(), GL_DEPTH_COMPONENT32F, width, height);
    glNamedFramebufferRenderbuffer(framebuffer_.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
    glNamedFramebufferDrawBuffers(framebuffer_.id(), 3, attachments);
    if (glCheckNamedFramebufferStatus(framebuffer_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("measurement framebuffer " + std::to_string(width) + "x" + std::to_string(height) +
                                 " is incomplete");
    width_ = width;
    height_ = height;
}

MeasureFrame MeasureTargets::read() const {
    MeasureFrame f;
    f.width = width_;
    f.height = height_;
    const std::size_t n = f.pixelCount();
    std::vector<glm::vec4> texels[3];
    for (int i = 0; i < 3; ++i) {
        texels[i].resize(n);
        glGetTextureImage(colour_[i].id(), 0, GL_RGBA, GL_FLOAT, GLsizei(n * sizeof(glm::vec4)), texels[i].data());
    }
    f.footprint.resize(n);
    f.bisectorFootprint.resize(n);
    f.eyeDepth.resize(n);
    f.shadowTerm.resize(n);
    f.position.resize(n);
    f.normal.resize(n);
    f.receiver.resize(n);
    f.surface.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        f.footprint[i] = texels[0][i].x;
        f.bisectorFootprint[i] = texels[0][i].y;
        f.eyeDepth[i] = texels[0][i].z;
        f.shadowTerm[i] = texels[0][i].w;
        f.position[i] = glm::vec3(texels[1][i]);
        f.receiver[i] = texels[1][i].w > 0.5f ? 1 : 0;
        f.normal[i] = glm::vec3(texels[2][i]);
        f.surface[i] = texels[2][i].w > 0.5f ? 1 : 0;
    }
    return f;
}

}  // namespace shadowlab
