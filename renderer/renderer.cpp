#include "renderer.h"
#include "renderer_frame.h"
#include "gl/sanitizer_support.h"
#include "resources/view_pool.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <initializer_list>
#include <cmath>

namespace shadowlab {

namespace {

// shaders/shadow_clip.glsl: the matrix relative to the camera (rounded to float, so that the
// shader's p - uShadowOrigin is exact for nearby p), composed in double.
void setShadowClip(const gl::Program& program, const glm::dmat4& worldToClip, const glm::dvec3& eye) {
    const glm::dvec3 origin{glm::vec3(eye)};
    program.set("uWorldToShadowClip", glm::mat4(worldToClip * glm::translate(glm::dmat4(1.0), origin)));
    program.set("uShadowOrigin", glm::vec3(origin));
}

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// The bindings every pass leaves behind as it found them: no texture or sampler on the units it
// used, no vertex array, program or framebuffer.
void unbindPassResources(std::initializer_list<GLuint> textureUnits) {
    for (GLuint unit : textureUnits) {
        glBindTextureUnit(unit, 0);
        glBindSampler(unit, 0);
    }
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace

bool Renderer::lightFacingIsCounterClockwise(const glm::dmat4& m, const LightFrame& light, const Aabb& body) {
    if (body.empty()) return true;
    const glm::dvec3 at = body.center();
    glm::dvec3 travel = light.type == LightType::Directional ? light.direction : at - light.position;
    if (!(glm::length(travel) > 0.0)) travel = light.direction;
    travel = glm::normalize(travel);
    // u x v = -travel: the triangle (at, at + u, at + v) faces the light, counter-clockwise seen from it.
    const glm::dvec3 helper = std::abs(travel.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    const double size = 1e-3 * std::max(1e-9, glm::length(body.extent()));
    const glm::dvec3 u = glm::normalize(glm::cross(travel, helper)) * size;
    const glm::dvec3 v = glm::cross(-travel, u / size) * size;
    auto ndc = [&](const glm::dvec3& p) {
        const glm::dvec4 h = m * glm::dvec4(p, 1.0);
        return glm::dvec2(h) / h.w;
    };
    const glm::dvec2 a = ndc(at), b = ndc(at + u), c = ndc(at + v);
    const double signedArea = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    return !(signedArea < 0.0);
}

std::unique_ptr<Renderer> Renderer::create(std::string& error) {
    gl::keepLoadedLibrariesMappedForLeakReports();  // the viewer's GLX context too (ASan builds only)
    std::unique_ptr<Renderer> r(new Renderer());
    auto forward = MaterialPrograms::build("forward.vert", "forward.frag", "", error);
    if (!forward) return nullptr;
    auto depth = MaterialPrograms::build("shadow_depth.vert", "shadow_depth.frag", "", error);
    if (!depth) return nullptr;
    auto depthLinear = MaterialPrograms::build("shadow_depth.vert", "shadow_depth.frag", "#define LINEAR_DEPTH 1\n", error);
    if (!depthLinear) return nullptr;
    auto blur = gl::Program::build("fullscreen.vert", "blur.frag", "", error);
    if (!blur) return nullptr;
    auto forwardCascaded = MaterialPrograms::build("forward.vert", "forward.frag", "#define CASCADES 1\n", error);
    if (!forwardCascaded) return nullptr;
    r->forwardCascaded_ = std::move(*forwardCascaded);
    r->forward_ = std::move(*forward);
    r->shadowDepth_ = std::move(*depth);
    r->shadowDepthLinear_ = std::move(*depthLinear);
    r->blur_ = std::move(*blur);
    r->emptyVao_ = gl::createVertexArray();
    return r;
}

void Renderer::setScene(const Scene& scene, bool streamTextures, LoadTimings* timings) {
    gpuScene_.reset();  // the old scene's buffers go before the new ones are made
    gpuScene_ = std::make_unique<GpuScene>(scene, streamTextures, timings);
    {
        StepTimer building(timings, &LoadStepTimes::bvhMs);
        culler_.setScene(scene);
    }
    scene_ = &scene;
    StepTimer modelling(timings, &LoadStepTimes::casterModelMs);
    backdrops_ = detectBackdrops(scene);
    ++sceneLoads_;
    ++sceneVersion_;
    contentVersion_ = sceneVersion_;
    instanceMoved_.assign(scene.instances.size(), 0);
}

std::size_t Renderer::streamTextures(double budgetMs) {
    if (!gpuScene_ || !scene_) return 0;
    if (gpuScene_->uploadPendingTextures(*scene_, budgetMs)) contentVersion_ = ++sceneVersion_;
    return gpuScene_->pendingTextures();
}

void Renderer::updateInstances(const Scene& scene) {
    if (!gpuScene_) return;
    gpuScene_->updateInstances(scene, &changedInstances_);
    if (changedInstances_.empty()) return;  // a pose that moved nothing redraws nothing
    culler_.updateInstances(scene);
    ++sceneVersion_;
    // Per instance, when it last moved: a shadow map is redrawn only when one of its casters did.
    instanceMoved_.resize(scene.instances.size(), 0);
    for (std::uint32_t i : changedInstances_) instanceMoved_[i] = sceneVersion_;
}

std::uint64_t Renderer::castersMoved(const InstanceList& casters) const {
    std::uint64_t latest = 0;
    for (std::uint32_t i : casters)
        if (i < instanceMoved_.size()) latest = std::max(latest, instanceMoved_[i]);
    return latest;
}

void Renderer::resolveTimings() {
    for (GpuTimer* t : {&shadowTimer_, &termTimer_, &blurTimer_, &forwardTimer_}) t->resolveBlocking();
    for (const auto& [pass, timer] : lastTimedPasses_)
        if (pass < lastStats_.passes.size()) lastStats_.passes[pass].gpuMs = timer->lastMs();
}

bool Renderer::timingsPending() const {
    for (const GpuTimer* t : {&shadowTimer_, &termTimer_, &blurTimer_, &forwardTimer_})
        if (t->pending()) return true;
    return false;
}

FrameStats Renderer::renderSettled(const Scene& scene, const Settings& settings, double seconds,
                                   const Viewport& viewport) {
    FrameStats stats = render(scene, settings, seconds, viewport);
    for (int frame = 1; frame < 3 && stats.needsAnotherFrame; ++frame) stats = render(scene, settings, seconds, viewport);
    return stats;
}

void Renderer::cullView(Frame& frame, FrameStats& stats) const {
    const auto start = Clock::now();
    const bool hierarchical = frame.settings.skip.hierarchicalCulling;
    culler_.visible(frame.scene, clipPlanes(frame.viewProjection), hierarchical, frame.visible);
    stats.instances = frame.scene.instances.size();
    stats.instancesVisible = frame.visible.size();
    stats.hierarchicalCulling = hierarchical;
    stats.cullingCpuMs += msSince(start);
}

void Renderer::cullCasters(Frame& frame, FrameStats& stats) const {
    const auto start = Clock::now();
    culler_.casters(frame.scene, frame.shadow, frame.settings.skip.hierarchicalCulling, frame.casters);
    stats.castersExcluded = keepCasting(frame.casterModel, frame.casters);
    stats.castersDrawn = frame.casters.size();
    stats.castersCulled = frame.scene.instances.size() - frame.casters.size() - stats.castersExcluded;
    stats.cullingCpuMs += msSince(start);
}

std::size_t Renderer::selectShadowMap(const ShadowMapKey& key, int views) {
    const std::size_t pool = viewPoolSize(views);  // view_pool.h
    if (shadowMaps_.size() != pool) {
        shadowMaps_.resize(pool);
        mapLastUse_.resize(pool, 0);
    }
    std::size_t held = 0;
    while (held < pool && !shadowMaps_[held].holds(key)) ++held;
    return takePoolSlot(mapLastUse_, held, mapUseClock_);
}

ShadowMapKey Renderer::shadowMapKey(const Frame& frame) const {
    const BiasSettings& bias = frame.settings.bias;
    const bool slope = bias.mode == DepthOffset::SlopeScale;
    ShadowMapKey key;
    key.scene = &frame.scene;
    key.sceneVersion = contentVersion_;
    key.castersMoved = castersMoved(frame.casters);
    key.size = frame.settings.shadowMapSize;
    key.worldToShadowClip = frame.worldToShadowClip;
    key.reversedDepth = frame.reversedDepth;
    key.linearDepth = frame.linearDepth;
    key.linear = frame.linear;
    key.mirrored = frame.shadowMapMirrored;
    key.offsetMode = int(bias.mode);
    key.slopeFactor = slope ? bias.slopeFactor : 0.0;
    key.slopeUnits = slope ? bias.slopeUnits : 0.0;
    key.singleSidedFaces = int(frame.casterModel.singleSided);
    key.doubleSidedFaces = int(frame.casterModel.doubleSided);
    key.casters = frame.casters;
    return key;
}

FrameStats Renderer::render(const Scene& scene, const Settings& settings, double seconds, const Viewport& viewport) {
    FrameStats stats;
    const auto setupStart = Clock::now();
    const double aspect = viewport.height > 0 ? double(viewport.width) / viewport.height : 1.0;
    const ViewFrustum view = viewFrustum(settings.camera, aspect);
    const ViewFrustum shadowCamera = shadowCameraRequest_ ? viewFrustum(*shadowCameraRequest_, aspect) : view;
    Frame frame{scene, settings, viewport, view, view.projectionMatrix() * view.viewMatrix(), shadowCamera,
                resolveLight(scene, settings.light, seconds), false, {}, glm::dmat4(1.0), false, false, {}, {}, {},
                false, {}, {}, {}, {}};
    stats.lightNote = frame.light.note;
    casterChoice_ = chooseCasters(scene, settings.casters, backdrops_);
    frame.casterModel = casterChoice_.model;
    frame.shadowBounds = castingBounds(scene, frame.casterModel);
    stats.casterFaces = casterFacesText(frame.casterModel);
    lastSetup_ = ShadowSetup{};  // a frame without shadows must not show the previous frame's B
    lastCascades_ = CascadeSetup{};
    if (!gpuScene_) return stats;
    cullView(frame, stats);

    if (settings.shadows && frame.light.castsShadow && settings.csm.enabled) {
        setupCascades(frame, stats);  // cascade_pass.cpp: per-split B_i, matrices, caster culling
    } else if (settings.shadows && frame.light.castsShadow) {
        const bool psmAutoNear = settings.method == ShadowMethod::Psm && settings.psm.autoNear;
        const bool lispsmAutoFar = settings.method == ShadowMethod::Lispsm && settings.lispsm.autoVirtualFar;
        // A warp chosen by measurement (LiSPSM's search, PSM's guard) needs this view's receivers:
        // without them it judges at stand-ins that bound where receivers can be, not where they are
        // (math/lispsm_search.h), so it gets the pre-pass whatever the other two features say and,
        // on a cut, waits for its read-back. Neither: no pre-pass at all.
        const bool warpNeedsReceivers = settings.method == ShadowMethod::Lispsm ||
                                        (settings.method == ShadowMethod::Psm && settings.psm.guard);
        const VisibleDepthRange visible = psmAutoNear || lispsmAutoFar || warpNeedsReceivers
                                              ? visibleDepthRange(frame, stats, warpNeedsReceivers)
                                              : VisibleDepthRange{};
        const ViewFrustum& shadowView = frame.shadowView;
        ShadowParams params = shadowParams(settings, shadowView, frame.shadowBounds);
        // Stamminger & Drettakis 4.2, 6: PSM's near plane as far as the visible geometry allows
        // (halved: a quarter-resolution pixel may miss thin geometry in front).
        if (psmAutoNear && 0.5 * visible.nearest > shadowView.zNear)
            params.psmNearPlane = std::min(0.5 * visible.nearest, 0.5 * shadowView.zFar);
        // Thesis 9.2.5: with a depth-only pass, z_f is the farthest visible depth.
        if (lispsmAutoFar && visible.farthest > 0.0)
            params.lispsm.virtualFar = std::clamp(visible.farthest, shadowView.zNear * 1.001, shadowView.zFar);
        // The nearest visible depth, symmetric to z_f: LiSPSM's warp search and PSM's guard
        // sample receivers from there on (math/lispsm_search.h).
        if (visible.nearest > 0.0 && (psmAutoNear || lispsmAutoFar)) params.lispsm.pseudoNear = visible.nearest;
        params.receiverPoints = visible.receivers;
        params.fineReceiverPoints = visible.fineReceivers;  // spot lights and the image check (visibleDepthRange)
        stats.virtualFarUsed = params.method == ShadowMethod::Lispsm ? params.lispsm.virtualFar : 0.0;
        frame.shadow = computeShadowSetup(shadowView, shadowLight(frame.light), frame.shadowBounds, params);
        stats.shadow = frame.shadow.diagnostics;
        lastSetup_ = frame.shadow;
        frame.shadowed = frame.shadow.valid;
    }
    if (frame.shadowed && !frame.cascaded) {
        frame.worldToShadowClip = frame.shadow.worldToShadowClip;  // w > 0 over B by contract
        frame.linearDepth = linearShadowDepth(settings);
        // Linear depth grows away from the light whatever the warp, so it never needs reversing.
        frame.reversedDepth = frame.shadow.reverseDepthTest && !frame.linearDepth;
        frame.linear = frame.shadow.linearDepth;
        frame.shadowMapMirrored =
            !lightFacingIsCounterClockwise(frame.worldToShadowClip, frame.light, frame.shadow.bodyBounds);
        cullCasters(frame, stats);
    }
    double prePassMs = 0.0;  // the PSM near pre-pass reports itself
    for (const PassStats& p : stats.passes) prePassMs += p.cpuMs;
    stats.passes.push_back({"setup + culling (CPU)", msSince(setupStart) - prePassMs, 0.0});
    timedPasses_.clear();

    if (frame.cascaded) {
        cascadeShadowPass(frame, stats);
    } else if (frame.shadowed) {
        // One view switched to one map frees the cascade arrays; a split compare that mixes one
        // map and cascades (lispsm | csm-lispsm) keeps them for its cascaded views.
        if (settings.compare.count <= 1)
            for (CascadeMaps& maps : cascadePool_) maps.release();
        ShadowMapKey key = shadowMapKey(frame);
        currentMap_ = selectShadowMap(key, settings.compare.count);
        stats.shadowMapReused = settings.skip.reuseShadowMap && shadowMap().holds(key);
        if (stats.shadowMapReused) {
            stats.shadowMapSize = shadowMap().size();
            stats.passes.push_back({"shadow map (reused)", 0.0, 0.0});
        } else {
            shadowPass(frame, stats);
            shadowMap().setContent(std::move(key));
        }
    }
    const bool blur = frame.shadowed && settings.filter.blurIterations > 0;
    if (blur) {
        shadowTermPass(frame, stats);
        blurPasses(frame, stats);
    } else {
        termTargets_.release();  // N = 0 keeps nothing extra allocated
    }
    forwardPass(frame, stats);
    if (measureRequest_.targets) measurePass(frame, stats);
    stats.trianglesDrawn = stats.shadowPass.triangles + stats.depthPrePass.triangles + stats.forwardPass.triangles;
    stats.drawCalls += stats.shadowPass.drawCalls + stats.depthPrePass.drawCalls + stats.forwardPass.drawCalls;
    lastStats_ = stats;
    lastTimedPasses_ = timedPasses_;
    return stats;
}

VisibleDepthRange Renderer::visibleDepthRange(const Frame& frame, FrameStats& stats, bool waitOnCut) {
    DepthView view;
    view.view = frame.shadowView;  // the pre-pass sees what the camera the shadows are for sees
    const bool ownCamera = shadowCameraRequest_ != nullptr;
    view.viewProjection =
        ownCamera ? frame.shadowView.projectionMatrix() * frame.shadowView.viewMatrix() : frame.viewProjection;
    InstanceList shadowCameraVisible;
    if (ownCamera)
        culler_.visible(frame.scene, clipPlanes(view.viewProjection), frame.settings.skip.hierarchicalCulling,
                        shadowCameraVisible);
    view.width = std::max(16, frame.viewport.width / 4);  // a quarter resolution is enough for a range
    view.height = std::max(16, frame.viewport.height / 4);
    view.sceneLoad = sceneLoads_;
    view.sceneVersion = sceneVersion_;
    // Spot lights (a cone lighting a few grid points), cascades (a split holding a few of them)
    // and the image check of a warp also sample the fine grid (math/lispsm_search.h,
    // math/cascades.h, math/image_check.h).
    view.fineReceivers =
        frame.light.type == LightType::Spot || frame.settings.csm.enabled || warpImageCheck(frame.settings);
    view.samples = frame.settings.csm.enabled && frame.settings.csm.placement == SplitPlacement::Sdsm;
    auto drawDepth = [&](const glm::dmat4& viewProjection) {
        const ProgramFor programs = passPrograms(shadowDepth_, true, frame.settings, [&](const gl::Program& p) {
            setShadowClip(p, viewProjection, frame.shadowView.eye);
        });
        drawScene(programs, frame, ownCamera ? shadowCameraVisible : frame.visible, kCameraSides, stats.depthPrePass);
    };
    const VisibleDepthRange range =
        visibleDepth_.range(view, frame.settings.skip.asyncDepthReadback, drawDepth, stats, waitOnCut);
    unbindPassResources({0});
    return range;
}

void Renderer::shadowPass(const Frame& frame, FrameStats& stats) {
    const auto cpuStart = Clock::now();
    shadowTimer_.begin();
    shadowMap().ensure(frame.settings.shadowMapSize);
    stats.shadowMapSize = shadowMap().size();
    drawShadowDepth(frame, shadowMap().framebuffer(), shadowMap().size(), stats.shadowPass);
    shadowTimer_.end();
    stats.passes.push_back({"shadow map", msSince(cpuStart), shadowTimer_.lastMs()});
    timedPasses_.push_back({stats.passes.size() - 1, &shadowTimer_});
}

void Renderer::drawShadowDepth(const Frame& frame, GLuint framebuffer, int size, PassCounts& counts) {
    const Settings& s = frame.settings;
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, size, size);
    // Inverted PSM lights store the far side as larger depth: clear to 0 and keep the greater.
    const GLfloat clearDepth = frame.reversedDepth ? 0.0f : 1.0f;
    glDepthMask(GL_TRUE);
    glClearBufferfv(GL_DEPTH, 0, &clearDepth);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(frame.reversedDepth ? GL_GREATER : GL_LESS);
    // Casters in front of the focused near plane still cast: clamp them onto it ("pancaking").
    glEnable(GL_DEPTH_CLAMP);
    if (s.bias.mode == DepthOffset::SlopeScale && !frame.linearDepth) {
        // Thesis eq. 5.2: bias = factor * dz + r * units, pushed away from the light (the linear
        // depth program applies it itself, since it writes gl_FragDepth).
        const float sign = frame.reversedDepth ? -1.0f : 1.0f;
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(sign * float(s.bias.slopeFactor), sign * float(s.bias.slopeUnits));
    }

    const bool slope = s.bias.mode == DepthOffset::SlopeScale;
    auto setup = [&](const gl::Program& program) {
        setShadowClip(program, frame.worldToShadowClip, frame.view.eye);
        program.set("uSlopeFactor", slope ? float(s.bias.slopeFactor) : 0.0f);
        program.set("uSlopeUnits", slope ? float(s.bias.slopeUnits) : 0.0f);
        program.set("uLinearRadial", frame.linear.radial ? 1 : 0);
        program.set("uLinearOrigin", glm::vec3(frame.linear.origin));
        program.set("uLinearAxis", glm::vec3(frame.linear.axis));
        program.set("uLinearRange", glm::vec2(frame.linear.nearDepth, frame.linear.farDepth));
    };
    const ProgramFor programs = passPrograms(frame.linearDepth ? shadowDepthLinear_ : shadowDepth_, true, s, setup);
    // The caster model's faces (frame/caster_model.h); `back` is thesis 5.1's back-face rendering.
    drawScene(programs, frame, frame.casters, frame.casterModel, counts, Surfaces::All, frame.shadowMapMirrored);

    glDisable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(0.0f, 0.0f);
    glDisable(GL_DEPTH_CLAMP);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    unbindPassResources({0});
}

void Renderer::setLightingUniforms(const gl::Program& program, const Frame& frame, bool useBlurredTerm) const {
    const Settings& s = frame.settings;
    const glm::dvec3 origin{glm::vec3(frame.view.eye)};  // as in setShadowClip
    program.set("uViewProjection", glm::mat4(frame.viewProjection * glm::translate(glm::dmat4(1.0), origin)));
    program.set("uViewOrigin", glm::vec3(origin));
    program.set("uCameraPosition", glm::vec3(frame.view.eye));
    const LightFrame& light = frame.light;
    program.set("uLightType", int(light.type));
    program.set("uLightDirection", glm::vec3(light.direction));
    program.set("uLightPosition", glm::vec3(light.position));
    program.set("uLightColor", glm::vec3(light.radiance));
    program.set("uLightCosOuter", float(light.cosOuter));
    program.set("uLightCosInner", float(light.cosInner));
    program.set("uLightRange", float(light.range));
    program.set("uAmbient", float(s.light.ambient));
    program.set("uHemisphereAmbient", s.display.hemisphereAmbient ? 1 : 0);
    program.set("uExposure", float(std::exp2(s.display.exposureEv)));
    program.set("uToneMapping", int(s.display.toneMapping));

    program.set("uShadowsEnabled", frame.shadowed ? 1 : 0);
    program.set("uUseBlurredTerm", useBlurredTerm ? 1 : 0);
    glProgramUniform2i(program.id(), program.location("uViewportOrigin"), frame.viewport.x, frame.viewport.y);
    program.set("uNormalOffset", float(s.bias.normalOffset));
    program.set("uAdaptiveBias", s.bias.mode == DepthOffset::Adaptive ? 1 : 0);
    program.set("uAdaptiveMargin", float(s.bias.adaptiveMargin));
    program.set("uAdaptiveCosMax", float(std::cos(glm::radians(s.bias.adaptiveMaxAngleDeg))));
    if (!frame.shadowed) return;
    setShadowClip(program, frame.worldToShadowClip, frame.view.eye);
    program.set("uReverseDepth", frame.reversedDepth ? 1 : 0);
    program.set("uLinearDepth", frame.linearDepth ? 1 : 0);
    program.set("uLinearRadial", frame.linear.radial ? 1 : 0);
    program.set("uLinearOrigin", glm::vec3(frame.linear.origin));
    program.set("uLinearAxis", glm::vec3(frame.linear.axis));
    program.set("uLinearRange", glm::vec2(frame.linear.nearDepth, frame.linear.farDepth));
    program.set("uShadowFilter", int(s.filter.filter));
    program.set("uConstantOffset", s.bias.mode == DepthOffset::Constant ? float(s.bias.constant) : 0.0f);
    if (frame.cascaded) {
        setCascadeUniforms(program, frame);  // cascade_pass.cpp: the array, per-split matrices
        return;
    }
    program.set("uShadowTexel", glm::vec2(1.0f / float(shadowMap().size())));
    glBindTextureUnit(1, shadowMap().texture());
    glBindSampler(1, shadowMap().sampler(s.filter.filter == ShadowFilter::Pcf2x2Hardware, frame.reversedDepth));
}

void Renderer::shadowTermPass(const Frame& frame, FrameStats& stats) {
    // Thesis 9.4.2: the PCF shadow term of the visible surfaces, written to a screen-sized texture.
    const auto cpuStart = Clock::now();
    termTimer_.begin();
    const Viewport& vp = frame.viewport;
    termTargets_.ensure(vp.width, vp.height);
    glBindFramebuffer(GL_FRAMEBUFFER, termTargets_.framebuffer(0));
    glViewport(0, 0, vp.width, vp.height);
    const GLfloat lit[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    const GLfloat farDepth = 1.0f;
    glClearBufferfv(GL_COLOR, 0, lit);
    glDepthMask(GL_TRUE);
    glClearBufferfv(GL_DEPTH, 0, &farDepth);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    Frame termFrame = frame;
    termFrame.viewport = Viewport{termTargets_.framebuffer(0), 0, 0, vp.width, vp.height};
    const ProgramFor programs = passPrograms(forwardFor(frame), false, frame.settings, [&](const gl::Program& program) {
        setLightingUniforms(program, termFrame, false);
        program.set("uOutputMode", 2);
    });
    drawScene(programs, frame, frame.visible, kCameraSides, stats.forwardPass);
    glDisable(GL_DEPTH_TEST);
    unbindPassResources({0, 1});
    termTimer_.end();
    stats.passes.push_back({"shadow term", msSince(cpuStart), termTimer_.lastMs()});
    timedPasses_.push_back({stats.passes.size() - 1, &termTimer_});
}

void Renderer::blurPasses(const Frame& frame, FrameStats& stats) {
    const auto cpuStart = Clock::now();
    blurTimer_.begin();
    const Settings& s = frame.settings;
    const Viewport& vp = frame.viewport;
    const gl::Program& program = blur_;
    program.use();
    program.set("uStrength", float(s.filter.blurStrength));
    program.set("uDepthDependent", s.filter.depthDependentBlur ? 1 : 0);
    program.set("uEdgeAware", s.filter.edgeAwareBlur ? 1 : 0);
    program.set("uNearFar", glm::vec2(float(frame.view.zNear), float(frame.view.zFar)));
    glBindVertexArray(emptyVao_.id());
    glViewport(0, 0, vp.width, vp.height);
    glDisable(GL_DEPTH_TEST);
    glBindTextureUnit(1, termTargets_.depth());
    glBindSampler(1, termTargets_.linearClampSampler());
    // Each iteration: horizontal (0 -> 1) then vertical (1 -> 0), so the result ends in texture 0.
    for (int i = 0; i < s.filter.blurIterations; ++i) {
        for (int direction = 0; direction < 2; ++direction) {
            glBindFramebuffer(GL_FRAMEBUFFER, termTargets_.framebuffer(1 - direction));
            glBindTextureUnit(0, termTargets_.term(direction));
            glBindSampler(0, termTargets_.linearClampSampler());
            program.set("uDirection", direction == 0 ? glm::vec2(1.0f / float(vp.width), 0.0f)
                                                     : glm::vec2(0.0f, 1.0f / float(vp.height)));
            glDrawArrays(GL_TRIANGLES, 0, 3);
            ++stats.drawCalls;
        }
    }
    unbindPassResources({0, 1});
    blurTimer_.end();
    stats.passes.push_back({"blur x" + std::to_string(s.filter.blurIterations), msSince(cpuStart), blurTimer_.lastMs()});
    timedPasses_.push_back({stats.passes.size() - 1, &blurTimer_});
}

void Renderer::forwardPass(const Frame& viewFrame, FrameStats& stats) {
    const auto cpuStart = Clock::now();
    forwardTimer_.begin();
    // Anti-aliasing (display.msaaSamples): draw into a multisampled target at its origin, resolve
    // into the view afterwards. Raw measurement frames are never averaged.
    const Viewport& view = viewFrame.viewport;
    const bool msaa = viewFrame.settings.display.msaaSamples > 1 && viewFrame.settings.viewMode != ViewMode::AliasingErrorRaw;
    Frame frame = viewFrame;
    if (msaa) {
        msaa_.ensure(view.width, view.height, viewFrame.settings.display.msaaSamples);
        frame.viewport = Viewport{msaa_.framebuffer(), 0, 0, view.width, view.height};
    } else {
        msaa_.release();
    }
    const Viewport& vp = frame.viewport;
    glBindFramebuffer(GL_FRAMEBUFFER, vp.framebuffer);
    glViewport(vp.x, vp.y, vp.width, vp.height);
    glEnable(GL_SCISSOR_TEST);
    glScissor(vp.x, vp.y, vp.width, vp.height);
    glEnable(GL_FRAMEBUFFER_SRGB);
    // Background: a sky colour given in linear space (the sRGB framebuffer encodes it).
    // Raw measurement frames clear to zero: "nothing measured here".
    const GLfloat sky[4] = {0.30f, 0.45f, 0.70f, 1.0f}, none[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    glClearBufferfv(GL_COLOR, 0, frame.settings.viewMode == ViewMode::AliasingErrorRaw ? none : sky);
    glDepthMask(GL_TRUE);
    const GLfloat farDepth = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &farDepth);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);

    const bool useBlurredTerm = frame.shadowed && termTargets_.allocated();
    if (useBlurredTerm) {
        glBindTextureUnit(2, termTargets_.term(0));
        glBindSampler(2, 0);
    }
    const ViewMode mode = frame.settings.viewMode;
    const int outputMode = mode == ViewMode::ShadowTermOnly     ? 1
                           : mode == ViewMode::AliasingError    ? 3
                           : mode == ViewMode::AliasingErrorRaw ? 4
                                                                : 0;
    const ProgramFor programs = passPrograms(forwardFor(frame), false, frame.settings, [&](const gl::Program& program) {
        setLightingUniforms(program, frame, useBlurredTerm);
        program.set("uOutputMode", outputMode);
    });
    // Raw measurement values are written as they are, not sRGB-encoded.
    if (mode == ViewMode::AliasingErrorRaw) glDisable(GL_FRAMEBUFFER_SRGB);

    // Opaque and masked surfaces first, then blended ones over them without depth writes.
    drawScene(programs, frame, frame.visible, kCameraSides, stats.forwardPass, Surfaces::OpaqueAndMasked);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    drawScene(programs, frame, frame.visible, kCameraSides, stats.forwardPass, Surfaces::Blended);

    // Restore what this pass changed.
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glDisable(GL_SCISSOR_TEST);
    if (msaa) msaa_.resolveInto(view.framebuffer, view.x, view.y);
    unbindPassResources({0, 1, 2});
    forwardTimer_.end();
    stats.passes.push_back({"forward", msSince(cpuStart), forwardTimer_.lastMs()});
    timedPasses_.push_back({stats.passes.size() - 1, &forwardTimer_});
}

}  // namespace shadowlab
