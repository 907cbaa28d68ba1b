#include "overlays/overlay.h"

#include <array>
#include <cstdint>

namespace shadowlab {

namespace {

// Records the state an overlay call changes and puts it back on destruction.
class GlStateGuard {
public:
    GlStateGuard() {
        for (std::size_t i = 0; i < kCaps.size(); ++i) enabled_[i] = glIsEnabled(kCaps[i]);
        glGetIntegerv(GL_VIEWPORT, viewport_.data());
        glGetIntegerv(GL_SCISSOR_BOX, scissor_.data());
        glGetIntegerv(GL_DEPTH_FUNC, &depthFunc_);
        glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
        glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vao_);
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
        glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
        glActiveTexture(GL_TEXTURE0);
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture0_);
        glGetIntegerv(GL_SAMPLER_BINDING, &sampler0_);
        glActiveTexture(GLenum(activeTexture_));
        glGetIntegerv(GL_CULL_FACE_MODE, &cullFace_);
        glGetIntegerv(GL_FRONT_FACE, &frontFace_);
    }
    ~GlStateGuard() {
        for (std::size_t i = 0; i < kCaps.size(); ++i) {
            if (enabled_[i])
                glEnable(kCaps[i]);
            else
                glDisable(kCaps[i]);
        }
        glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
        glScissor(scissor_[0], scissor_[1], scissor_[2], scissor_[3]);
        glDepthFunc(GLenum(depthFunc_));
        glDepthMask(depthMask_);
        glUseProgram(GLuint(program_));
        glBindVertexArray(GLuint(vao_));
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawFramebuffer_));
        glBindTextureUnit(0, GLuint(texture0_));
        glBindSampler(0, GLuint(sampler0_));
        glActiveTexture(GLenum(activeTexture_));
        glCullFace(GLenum(cullFace_));
        glFrontFace(GLenum(frontFace_));
    }
    GlStateGuard(const GlStateGuard&) = delete;
    GlStateGuard& operator=(const GlStateGuard&) = delete;

private:
    static constexpr std::array<GLenum, 7> kCaps{GL_DEPTH_TEST, GL_SCISSOR_TEST,     GL_DEPTH_CLAMP,        GL_BLEND,
                                                 GL_CULL_FACE,  GL_FRAMEBUFFER_SRGB, GL_POLYGON_OFFSET_FILL};
    std::array<GLboolean, 7> enabled_{};
    std::array<GLint, 4> viewport_{}, scissor_{};
    GLint depthFunc_ = GL_LESS;
    GLboolean depthMask_ = GL_TRUE;
    GLint program_ = 0, vao_ = 0, drawFramebuffer_ = 0, activeTexture_ = GL_TEXTURE0, texture0_ = 0, sampler0_ = 0;
    GLint cullFace_ = GL_BACK, frontFace_ = GL_CCW;
};

// Viewport and scissor on the rectangle, nothing else enabled.
void enterRect(GLuint framebuffer, const InsetRect& r) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    glViewport(r.x, r.y, r.width, r.height);
    glEnable(GL_SCISSOR_TEST);
    glScissor(r.x, r.y, r.width, r.height);
    for (GLenum cap :
         {GL_DEPTH_TEST, GL_DEPTH_CLAMP, GL_BLEND, GL_CULL_FACE, GL_FRAMEBUFFER_SRGB, GL_POLYGON_OFFSET_FILL})
        glDisable(cap);
}

}  // namespace

std::unique_ptr<OverlayRenderer> OverlayRenderer::create(std::string& error) {
    std::unique_ptr<OverlayRenderer> r(new OverlayRenderer());
    auto lines = gl::Program::build("overlay_lines.vert", "overlay_lines.frag", "", error);
    if (!lines) return nullptr;
    auto scene = gl::Program::build("inset_scene.vert", "inset_scene.frag", "", error);
    if (!scene) return nullptr;
    auto depth = gl::Program::build("fullscreen.vert", "inset_depth.frag", "", error);
    if (!depth) return nullptr;
    auto depthLayers = gl::Program::build("fullscreen.vert", "inset_depth.frag", "#define LAYERED 1\n", error);
    if (!depthLayers) return nullptr;
    r->depthLayers_ = std::move(*depthLayers);
    r->lines_ = std::move(*lines);
    r->scene_ = std::move(*scene);
    r->depth_ = std::move(*depth);
    r->emptyVao_ = gl::createVertexArray();
    r->lineVao_ = gl::createVertexArray();
    r->lineBuffer_ = gl::createBuffer();
    glEnableVertexArrayAttrib(r->lineVao_.id(), 0);
    glVertexArrayAttribFormat(r->lineVao_.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(r->lineVao_.id(), 0, 0);
    r->depthSampler_ = gl::createSampler();
    // Plain reads of the depth values: no compare mode, nearest, clamped.
    glSamplerParameteri(r->depthSampler_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(r->depthSampler_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(r->depthSampler_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(r->depthSampler_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(r->depthSampler_.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
    return r;
}

void OverlayRenderer::drawFrame(GLuint framebuffer, const InsetRect& rect) const {
    if (rect.empty()) return;
    GlStateGuard guard;
    // Border: the rectangle grown by 2 pixels in a light grey, then the inside in the background.
    const InsetRect outer{rect.x - 2, rect.y - 2, rect.width + 4, rect.height + 4};
    enterRect(framebuffer, outer);
    const GLfloat border[4] = {0.75f, 0.75f, 0.75f, 1.0f};
    glClearBufferfv(GL_COLOR, 0, border);
    enterRect(framebuffer, rect);
    const GLfloat background[4] = {0.12f, 0.12f, 0.14f, 1.0f};
    glClearBufferfv(GL_COLOR, 0, background);
}

void OverlayRenderer::drawDepthInset(GLuint framebuffer, const InsetRect& rect, GLuint depthTexture,
                                     bool reversed, glm::vec2 window) const {
    if (rect.empty() || depthTexture == 0) return;
    GlStateGuard guard;
    enterRect(framebuffer, rect);
    depth_.use();
    depth_.set("uReversed", reversed ? 1 : 0);
    depth_.set("uWindow", window);
    glBindTextureUnit(0, depthTexture);
    glBindSampler(0, depthSampler_.id());
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

std::vector<InsetRect> layerSquares(const InsetRect& rect, int layers) {
    std::vector<InsetRect> squares;
    if (rect.empty() || layers <= 0) return squares;
    const int side = std::min(rect.height, (rect.width - kLayerGap * (layers - 1)) / layers);
    if (side < 4) return squares;
    for (int i = 0; i < layers; ++i) squares.push_back({rect.x + i * (side + kLayerGap), rect.y, side, side});
    return squares;
}

std::vector<InsetRect> OverlayRenderer::drawDepthLayersInset(GLuint framebuffer, const InsetRect& rect,
                                                             GLuint arrayTexture, int layers, glm::vec2 window) const {
    if (arrayTexture == 0) return {};
    const std::vector<InsetRect> squares = layerSquares(rect, layers);
    if (squares.empty()) return squares;
    GlStateGuard guard;
    const int strip = std::max(2, squares[0].width / 24);
    for (int i = 0; i < int(squares.size()); ++i) {
        const InsetRect& square = squares[std::size_t(i)];
        enterRect(framebuffer, square);
        depthLayers_.use();
        depthLayers_.set("uReversed", 0);  // cascades never reverse the test (only PSM's inverted light does)
        depthLayers_.set("uLayer", i);
        depthLayers_.set("uWindow", window);
        glBindTextureUnit(0, arrayTexture);
        glBindSampler(0, depthSampler_.id());
        glBindVertexArray(emptyVao_.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        // The split's colour along the top edge (GL's origin is bottom-left).
        glScissor(square.x, square.y + square.height - strip, square.width, strip);
        const glm::vec4 c = cascadeColor(i);
        glClearBufferfv(GL_COLOR, 0, &c.x);
    }
    return squares;
}

void OverlayRenderer::drawScene(GLuint framebuffer, const InsetRect& rect, const Scene& scene, const GpuScene& gpu,
                                const glm::dmat4& worldToClip, const glm::dvec3& lightDirection,
                                bool reversedDepth) const {
    if (rect.empty()) return;
    GlStateGuard guard;
    enterRect(framebuffer, rect);
    const GLfloat clearDepth = reversedDepth ? 0.0f : 1.0f;
    glDepthMask(GL_TRUE);
    glClearBufferfv(GL_DEPTH, 0, &clearDepth);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(reversedDepth ? GL_GREATER : GL_LESS);
    glEnable(GL_DEPTH_CLAMP);  // what lies beyond the near/far planes is drawn flattened onto them
    glEnable(GL_FRAMEBUFFER_SRGB);
    scene_.use();
    scene_.set("uWorldToClip", glm::mat4(worldToClip));
    const double len = glm::length(lightDirection);
    scene_.set("uTowardsLight", glm::vec3(len > 0.0 ? -lightDirection / len : glm::dvec3(0, 1, 0)));
    const GLint materialLocation = scene_.location("uMaterial");
    gpu.bindVertexArray();
    gpu.forEachRun(scene, InstanceMask{}, [&](const GpuPrimitive& prim, GLuint firstSlot, GLsizei count, bool) {
        const GpuMaterial& m = gpu.material(prim.material);  // material.glsl: the entry of its buffer
        glProgramUniform1i(scene_.id(), materialLocation, m.slot);
        glBindTextureUnit(0, m.texture);
        glBindSampler(0, m.sampler);
        glDrawElementsInstancedBaseVertexBaseInstance(
            GL_TRIANGLES, prim.indexCount, GL_UNSIGNED_INT,
            reinterpret_cast<const void*>(std::uintptr_t(prim.firstIndex) * sizeof(std::uint32_t)), count,
            prim.baseVertex, firstSlot);
    });
}

void OverlayRenderer::drawWires(GLuint framebuffer, const InsetRect& rect, const std::vector<WireSet>& wires,
                                const glm::dmat4& worldToClip) const {
    if (rect.empty() || wires.empty()) return;
    // One buffer for all sets; float positions relative to nothing (the overlays are small).
    std::vector<glm::vec3> points;
    std::vector<std::pair<GLint, GLsizei>> ranges;
    for (const WireSet& w : wires) {
        ranges.emplace_back(GLint(points.size()), GLsizei(w.segments.size()));
        for (const glm::dvec3& p : w.segments) points.emplace_back(p);
    }
    if (points.empty()) return;
    GlStateGuard guard;
    enterRect(framebuffer, rect);
    const GLsizeiptr bytes = GLsizeiptr(points.size() * sizeof(glm::vec3));
    if (bytes > lineBufferBytes_) {
        lineBuffer_ = gl::createBuffer();
        glNamedBufferData(lineBuffer_.id(), bytes, nullptr, GL_DYNAMIC_DRAW);
        lineBufferBytes_ = bytes;
    }
    glNamedBufferSubData(lineBuffer_.id(), 0, bytes, points.data());
    glVertexArrayVertexBuffer(lineVao_.id(), 0, lineBuffer_.id(), 0, sizeof(glm::vec3));
    glBindVertexArray(lineVao_.id());
    lines_.use();
    lines_.set("uWorldToClip", glm::mat4(worldToClip));
    // 1-pixel lines drawn at two offsets: two pixels wide without glLineWidth (core profile).
    const glm::vec2 pixel(2.0f / float(rect.width), 2.0f / float(rect.height));
    for (const glm::vec2 offset : {glm::vec2(0.0f), glm::vec2(pixel.x, 0.0f), glm::vec2(0.0f, pixel.y)}) {
        lines_.set("uPixelOffset", offset);
        for (std::size_t i = 0; i < wires.size(); ++i) {
            lines_.set("uColor", wires[i].color);
            glDrawArrays(GL_LINES, ranges[i].first, ranges[i].second);
        }
    }
}

}  // namespace shadowlab
