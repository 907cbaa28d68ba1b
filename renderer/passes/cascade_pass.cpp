// Cascaded shadow maps in the frame (math/cascades.h for the math): the per-split setups and
// caster culling, one shadow pass per split into its layer of the depth array, and the uniforms
// of the lookup (shaders/cascade.glsl, compiled in by #define CASCADES).
#include "renderer.h"
#include "renderer_frame.h"
#include "resources/view_pool.h"

#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <string>

namespace shadowlab {

namespace {

// A split that sees nothing lit (B_i empty) maps every point to depth 0 at the map's centre: its
// cleared layer (depth 1) then reads lit, as the single map does for an invalid setup.
glm::dmat4 allLitMatrix() {
    glm::dmat4 m(0.0);
    m[3][2] = -1.0;
    m[3][3] = 1.0;
    return m;
}

glm::dmat4 splitMatrix(const CascadeSplit& split) {
    return split.setup.valid ? split.setup.worldToShadowClip : allLitMatrix();
}

const CascadeSplit* firstValidSplit(const CascadeSetup& cascades) {
    for (const CascadeSplit& split : cascades.splits)
        if (split.setup.valid) return &split;
    return nullptr;
}

}  // namespace

MaterialPrograms& Renderer::forwardFor(const Frame& frame) { return frame.cascaded ? forwardCascaded_ : forward_; }

void Renderer::setupCascades(Frame& frame, FrameStats& stats) {
    const Settings& s = frame.settings;
    CascadeParams params;
    params.splits = s.csm.splits;
    params.lambda = s.csm.lambda;
    params.manualSplits = s.csm.manualSplits;
    params.perSplit = s.csm.perSplit;
    params.mapResolution = s.shadowMapSize;
    params.base = shadowParams(s, frame.shadowView, frame.shadowBounds);
    // The visible depth range and receivers (depth pre-pass): the splits cover what is seen, and
    // each split's LiSPSM search measures the receivers of its own range (math/cascades.h).
    const bool sdsm = s.csm.placement == SplitPlacement::Sdsm;
    params.placement = s.csm.placement;
    if (s.csm.fitVisibleDepth || sdsm) {
        VisibleDepthRange visible = visibleDepthRange(frame, stats);
        if (s.csm.fitVisibleDepth) {
            params.visibleNear = visible.nearest;
            params.visibleFar = visible.farthest;
            params.base.receiverPoints = visible.receivers;
            params.base.fineReceiverPoints = visible.fineReceivers;  // each split's own (math/cascades.h)
        }
        // Samples bound the receivers only when they are this view's (a previous frame's, or a
        // cut's none, would cut off what the camera now sees): lambda otherwise, said in the note.
        const bool exact = stats.visibleDepth == VisibleDepthSource::Measured || stats.visibleDepth == VisibleDepthSource::Cached;
        if (sdsm && exact) params.samples = std::move(visible.samples);
    }
    frame.cascades = computeCascadeSetup(frame.shadowView, shadowLight(frame.light), frame.shadowBounds, params);
    lastCascades_ = frame.cascades;
    const CascadeSplit* first = firstValidSplit(frame.cascades);
    if (!frame.cascades.error.empty() || !first) {
        stats.shadow.fallback = frame.cascades.error;
        return;
    }
    frame.cascaded = true;
    frame.shadowed = true;
    frame.shadow = first->setup;  // overlays and read-outs show the first split that sees something
    stats.shadow = frame.shadow.diagnostics;
    // sdsm asked for but the practical scheme used (no samples of this view): the fallback line says so.
    if (!frame.cascades.placementNote.empty())
        stats.shadow.fallback += (stats.shadow.fallback.empty() ? "" : "; ") + frame.cascades.placementNote;
    lastSetup_ = frame.shadow;
    frame.linearDepth = linearShadowDepth(s);
    frame.reversedDepth = false;  // SSM, stable SSM and LiSPSM never reverse the test (only PSM does)
    frame.linear = first->setup.linearDepth;

    // Each split culls its casters against its own B_i.
    const auto start = std::chrono::steady_clock::now();
    frame.cascadeCasters.assign(frame.cascades.splits.size(), {});
    stats.castersDrawn = 0;
    for (std::size_t i = 0; i < frame.cascades.splits.size(); ++i) {
        const CascadeSplit& split = frame.cascades.splits[i];
        if (!split.setup.valid) continue;
        culler_.casters(frame.scene, split.setup, s.skip.hierarchicalCulling, frame.cascadeCasters[i]);
        stats.castersExcluded += keepCasting(frame.casterModel, frame.cascadeCasters[i]);
        stats.castersDrawn += frame.cascadeCasters[i].size();
    }
    stats.castersCulled =
        frame.scene.instances.size() * frame.cascades.splits.size() - stats.castersDrawn - stats.castersExcluded;
    stats.cullingCpuMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

std::size_t Renderer::selectCascadeMaps(const std::vector<ShadowMapKey>& layerKeys, int views) {
    // One array per view of a split compare (view_pool.h): the one holding most of this frame's
    // layers, else the least recently used.
    const std::size_t pool = viewPoolSize(views);
    if (cascadePool_.size() != pool) {
        cascadePool_.resize(pool);
        cascadeLastUse_.resize(pool, 0);
    }
    std::size_t held = pool;
    int best = 0;
    for (std::size_t p = 0; p < pool; ++p) {
        int layers = 0;
        for (std::size_t i = 0; i < layerKeys.size(); ++i) layers += cascadePool_[p].holds(int(i), layerKeys[i]) ? 1 : 0;
        if (layers > best) held = p, best = layers;
    }
    return takePoolSlot(cascadeLastUse_, held, mapUseClock_);
}

void Renderer::cascadeShadowPass(const Frame& frame, FrameStats& stats) {
    const auto cpuStart = std::chrono::steady_clock::now();
    shadowTimer_.begin();
    const int layers = int(frame.cascades.splits.size());
    const int size = frame.settings.shadowMapSize;
    std::vector<Frame> layerFrames;
    std::vector<ShadowMapKey> keys;
    for (int i = 0; i < layers; ++i) {
        const CascadeSplit& split = frame.cascades.splits[std::size_t(i)];
        Frame layer = frame;
        layer.worldToShadowClip = splitMatrix(split);
        layer.linear = split.setup.linearDepth;
        layer.casters = split.setup.valid ? frame.cascadeCasters[std::size_t(i)] : InstanceList{};
        layer.shadowMapMirrored =
            split.setup.valid && !lightFacingIsCounterClockwise(layer.worldToShadowClip, frame.light, split.setup.bodyBounds);
        keys.push_back(shadowMapKey(layer));
        layerFrames.push_back(std::move(layer));
    }
    currentCascades_ = selectCascadeMaps(keys, frame.settings.compare.count);
    cascadeMaps().ensure(size, layers);
    stats.shadowMapSize = size;
    stats.cascadeLayersReused = 0;
    for (int i = 0; i < layers; ++i) {
        // Per layer, as the single map (skip.reuseShadowMap): a split whose matrix, depth range
        // and casters did not change keeps its layer.
        if (frame.settings.skip.reuseShadowMap && cascadeMaps().holds(i, keys[std::size_t(i)])) {
            ++stats.cascadeLayersReused;
            continue;
        }
        drawShadowDepth(layerFrames[std::size_t(i)], cascadeMaps().framebuffer(i), size, stats.shadowPass);
        cascadeMaps().setContent(i, std::move(keys[std::size_t(i)]));
    }
    shadowTimer_.end();
    stats.shadowMapReused = layers > 0 && stats.cascadeLayersReused == layers;
    const double cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpuStart).count();
    // (A fixed name: the bench groups the passes of its repeats by name; cascadeLayersReused says
    // how many layers were kept.)
    stats.passes.push_back({"shadow maps (" + std::to_string(layers) + " splits)", cpuMs, shadowTimer_.lastMs()});
    timedPasses_.push_back({stats.passes.size() - 1, &shadowTimer_});
}

void Renderer::setCascadeUniforms(const gl::Program& program, const Frame& frame) const {
    const Settings& s = frame.settings;
    const CascadeSetup& cascades = frame.cascades;
    const glm::dmat4 toOrigin = glm::translate(glm::dmat4(1.0), glm::dvec3(glm::vec3(frame.view.eye)));  // as setShadowClip
    program.set("uCascadeCount", int(cascades.splits.size()));
    // The split of a point: its depth along the view the splits were made for (frame.shadowView),
    // from the origin the shader's points are relative to.
    const glm::dvec3 splitForward = glm::normalize(frame.shadowView.forward);
    program.set("uCascadeForward", glm::vec3(splitForward));
    program.set("uCascadeDepthOffset", float(glm::dot(frame.shadowView.eye - glm::dvec3(glm::vec3(frame.view.eye)), splitForward)));
    program.set("uCascadeBlend", float(s.csm.blendBand));
    program.set("uCascadeColors", s.csm.colorSplits ? 1 : 0);
    // Bias per split: a constant offset means the same world distance per texel in every split, so
    // it grows with the split's texel size and is converted to the split's depth units (its B_i
    // depth range), relative to the first split that sees something.
    const CascadeSplit& reference = *firstValidSplit(cascades);
    const double referenceRange = reference.setup.linearDepth.farDepth - reference.setup.linearDepth.nearDepth;
    const double constant = s.bias.mode == DepthOffset::Constant ? s.bias.constant : 0.0;
    for (std::size_t i = 0; i < cascades.splits.size(); ++i) {
        const CascadeSplit& split = cascades.splits[i];
        std::string index(1, '[');  // appended, not "[" + ...: gcc 12 warns falsely (-Wrestrict) on that
        index.append(std::to_string(i)).push_back(']');
        program.set("uCascadeClip" + index, glm::mat4(splitMatrix(split) * toOrigin));
        program.set("uCascadeNear" + index, float(split.zNear));
        program.set("uCascadeFar" + index, float(split.zFar));
        const LinearShadowDepth& linear = split.setup.linearDepth;
        program.set("uCascadeLinearRange" + index, glm::vec2(linear.nearDepth, linear.farDepth));
        const double range = linear.farDepth - linear.nearDepth;
        const double scale = split.setup.valid && range > 0.0 && reference.texelWorldSize > 0.0
                                 ? (referenceRange / range) * (split.texelWorldSize / reference.texelWorldSize)
                                 : 1.0;
        program.set("uCascadeOffset" + index, float(constant * scale));
    }
    program.set("uLinearRange", glm::vec2(0.0f, 1.0f));  // raw distance: the split's range applies per fragment
    program.set("uShadowTexel", glm::vec2(1.0f / float(cascadeMaps().size())));
    glBindTextureUnit(1, cascadeMaps().texture());
    glBindSampler(1, cascadeMaps().sampler(s.filter.filter == ShadowFilter::Pcf2x2Hardware));
}

}  // namespace shadowlab
