#include "renderer.h"

#include <chrono>

namespace shadowlab {

namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// Culling for one draw run: front faces are counter-clockwise unless the instance mirrors space.
void setWinding(bool mirrored) { glFrontFace(mirrored ? GL_CW : GL_CCW); }

}  // namespace

struct Renderer::Frame {
    const Scene& scene;
    const Settings& settings;
    Viewport viewport;
    ViewFrustum view;
    glm::dmat4 viewProjection;
    LightFrame light;
};

std::unique_ptr<Renderer> Renderer::create(std::string& error) {
    std::unique_ptr<Renderer> r(new Renderer());
    auto forward = gl::Program::build("forward.vert", "forward.frag", "", error);
    if (!forward) return nullptr;
    r->forward_ = std::move(*forward);
    return r;
}

void Renderer::setScene(const Scene& scene) { gpuScene_ = std::make_unique<GpuScene>(scene); }

void Renderer::updateInstances(const Scene& scene) {
    if (gpuScene_) gpuScene_->updateInstances(scene);
}

void Renderer::resolveTimings() { forwardTimer_.resolveBlocking(); }

void Renderer::setMaterial(const gl::Program& program, const Scene& scene, int materialIndex) const {
    static const Material kDefault{};
    const Material& m = materialIndex >= 0 && materialIndex < int(scene.materials.size())
                            ? scene.materials[std::size_t(materialIndex)]
                            : kDefault;
    program.set("uBaseColorFactor", m.baseColorFactor);
    const GLuint texture = gpuScene_->texture(m.baseColorTexture);
    program.set("uHasBaseColorTexture", texture != 0 ? 1 : 0);
    glBindTextureUnit(0, texture);
    glBindSampler(0, gpuScene_->sampler(m.baseColorTexture));
    program.set("uAlphaMode", int(m.alphaMode));
    program.set("uAlphaCutoff", m.alphaCutoff);
    program.set("uEmissive", m.emissiveFactor);
    if (m.doubleSided) glDisable(GL_CULL_FACE);
    else glEnable(GL_CULL_FACE);
}

FrameStats Renderer::render(const Scene& scene, const Settings& settings, double seconds, const Viewport& viewport) {
    FrameStats stats;
    const double aspect = viewport.height > 0 ? double(viewport.width) / viewport.height : 1.0;
    const ViewFrustum view = viewFrustum(settings.camera, aspect);
    Frame frame{scene, settings, viewport, view, view.projectionMatrix() * view.viewMatrix(),
                resolveLight(scene, settings.light, seconds)};
    stats.lightNote = frame.light.note;
    if (!gpuScene_) return stats;
    forwardPass(frame, stats);
    return stats;
}

void Renderer::forwardPass(const Frame& frame, FrameStats& stats) {
    const auto cpuStart = Clock::now();
    forwardTimer_.begin();
    const Viewport& vp = frame.viewport;
    glBindFramebuffer(GL_FRAMEBUFFER, vp.framebuffer);
    glViewport(vp.x, vp.y, vp.width, vp.height);
    glEnable(GL_SCISSOR_TEST);
    glScissor(vp.x, vp.y, vp.width, vp.height);
    glEnable(GL_FRAMEBUFFER_SRGB);
    // Background: a sky colour given in linear space (the sRGB framebuffer encodes it).
    const GLfloat sky[4] = {0.30f, 0.45f, 0.70f, 1.0f};
    glClearBufferfv(GL_COLOR, 0, sky);
    glDepthMask(GL_TRUE);
    const GLfloat farDepth = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &farDepth);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glCullFace(GL_BACK);

    const gl::Program& program = forward_;
    program.use();
    program.set("uViewProjection", glm::mat4(frame.viewProjection));
    program.set("uCameraPosition", glm::vec3(frame.view.eye));
    const LightFrame& light = frame.light;
    program.set("uLightType", int(light.type));
    program.set("uLightDirection", glm::vec3(light.direction));
    program.set("uLightPosition", glm::vec3(light.position));
    program.set("uLightColor", glm::vec3(light.radiance));
    program.set("uLightCosOuter", float(light.cosOuter));
    program.set("uLightCosInner", float(light.cosInner));
    program.set("uLightRange", float(light.range));
    program.set("uAmbient", float(frame.settings.light.ambient));
    program.set("uShadowTermOnly", frame.settings.viewMode == ViewMode::ShadowTermOnly ? 1 : 0);

    gpuScene_->bindVertexArray();
    const Scene& scene = frame.scene;
    // Opaque and masked surfaces first, then blended ones over them without depth writes.
    for (int blendPass = 0; blendPass < 2; ++blendPass) {
        if (blendPass == 1) {
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            glDepthMask(GL_FALSE);
        }
        gpuScene_->forEachRun(scene, {}, [&](const GpuPrimitive& prim, GLuint firstSlot, GLsizei count, bool mirrored) {
            const bool blended = prim.material >= 0 && prim.material < int(scene.materials.size()) &&
                                 scene.materials[std::size_t(prim.material)].alphaMode == AlphaMode::Blend;
            if (blended != (blendPass == 1)) return;
            setMaterial(program, scene, prim.material);
            setWinding(mirrored);
            glDrawElementsInstancedBaseVertexBaseInstance(
                GL_TRIANGLES, prim.indexCount, GL_UNSIGNED_INT,
                reinterpret_cast<const void*>(std::uintptr_t(prim.firstIndex) * sizeof(std::uint32_t)), count,
                prim.baseVertex, firstSlot);
            ++stats.drawCalls;
            stats.trianglesDrawn += std::size_t(prim.indexCount / 3) * std::size_t(count);
        });
    }

    // Restore what this pass changed.
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glDisable(GL_SCISSOR_TEST);
    glBindTextureUnit(0, 0);
    glBindSampler(0, 0);
    glBindVertexArray(0);
    glUseProgram(0);
    forwardTimer_.end();
    stats.passes.push_back({"forward", msSince(cpuStart), forwardTimer_.lastMs()});
}

}  // namespace shadowlab
