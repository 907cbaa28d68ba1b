// The measurement pass: the visible opaque and masked surfaces once more, with the frame's shadow
// map and lighting, into float targets (shaders/measure.frag), then read back for the accuracy
// instruments (footprints, error along depth, ground-truth comparison).
#include "renderer.h"
#include "renderer_frame.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace shadowlab {

FrameStats Renderer::renderMeasured(const Scene& scene, const Settings& settings, double seconds,
                                    const Viewport& viewport, MeasureFrame& out, const CameraSettings* shadowCamera) {
    struct Reset {
        MeasureRequest& request;
        const CameraSettings*& shadowCamera;
        ~Reset() { request = {}, shadowCamera = nullptr; }
    } reset{measureRequest_, shadowCameraRequest_};  // a throwing pass must not leave the requests armed
    shadowCameraRequest_ = shadowCamera;
    // The measured frame is the settled one (the async visible-depth readback has arrived).
    renderSettled(scene, settings, seconds, viewport);
    measureRequest_ = {&measureTargets_, &out};
    out = MeasureFrame{};
    return render(scene, settings, seconds, viewport);
}

void Renderer::measurePass(const Frame& frame, FrameStats& stats) {
    const auto cpuStart = std::chrono::steady_clock::now();
    gl::Program& measureProgram = frame.cascaded ? measureCascaded_ : measure_;
    if (!measureProgram) {
        std::string error;
        auto program =
            gl::Program::build("forward.vert", "measure.frag", frame.cascaded ? "#define CASCADES 1\n" : "", error);
        if (!program) throw std::runtime_error(error);
        measureProgram = std::move(*program);
    }
    MeasureTargets& targets = *measureRequest_.targets;
    const int w = frame.viewport.width, h = frame.viewport.height;
    targets.ensure(w, h);
    glBindFramebuffer(GL_FRAMEBUFFER, targets.framebuffer());
    glViewport(0, 0, w, h);
    const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f}, farDepth = 1.0f;
    for (int i = 0; i < 3; ++i) glClearBufferfv(GL_COLOR, i, zero);
    glDepthMask(GL_TRUE);
    glClearBufferfv(GL_DEPTH, 0, &farDepth);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);

    const gl::Program& program = measureProgram;
    program.use();
    Frame local = frame;
    local.viewport = Viewport{targets.framebuffer(), 0, 0, w, h};
    const bool useBlurredTerm = frame.shadowed && termTargets_.allocated();
    setLightingUniforms(program, local, useBlurredTerm);
    if (useBlurredTerm) {
        glBindTextureUnit(2, termTargets_.term(0));
        glBindSampler(2, 0);
    }
    // The view ray with axial component 1 and its change per pixel, from the look-at basis
    // (rows of the view matrix: right, up, -forward).
    const glm::dmat4 v = frame.view.viewMatrix();
    const glm::dvec3 right(v[0][0], v[1][0], v[2][0]), up(v[0][1], v[1][1], v[2][1]);
    const glm::dvec3 forward = -glm::dvec3(v[0][2], v[1][2], v[2][2]);
    const double perPixel = 2.0 * std::tan(0.5 * frame.view.fovY) / double(h);  // square pixels
    program.set("uEye", glm::vec3(frame.view.eye));
    program.set("uViewForward", glm::vec3(forward));
    program.set("uPixelRayDx", glm::vec3(right * perPixel));
    program.set("uPixelRayDy", glm::vec3(up * perPixel));
    if (!frame.shadowed) program.set("uShadowTexel", glm::vec2(1.0f));
    PassCounts drawCounts;
    drawScene(program, frame, frame.visible, kCameraSides, drawCounts, Surfaces::OpaqueAndMasked);

    glDisable(GL_DEPTH_TEST);
    for (GLuint unit : {0u, 1u, 2u}) {
        glBindTextureUnit(unit, 0);
        glBindSampler(unit, 0);
    }
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    MeasureFrame& out = *measureRequest_.out;
    out = targets.read();
    out.eye = frame.view.eye;
    out.fovYRad = frame.view.fovY;
    out.zNear = frame.view.zNear;
    out.zFar = frame.view.zFar;
    out.shadowMapSize = frame.cascaded ? cascadeMaps().size() : frame.shadowed ? shadowMap().size() : 0;
    out.casters = frame.casterModel;
    stats.passes.push_back(
        {"measure (+ read-back)", std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpuStart).count(),
         0.0});
}

}  // namespace shadowlab
