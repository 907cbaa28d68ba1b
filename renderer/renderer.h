#pragma once
// The frame: passes with explicit inputs and outputs, run by the same code in a GLFW window and in
// a headless EGL context. Each pass sets the whole pipeline state it needs and restores what it
// changed, so one pass never leaks culling, polygon offset or sRGB into the next.
//
//   view culling  ->  [visible-depth pre-pass, PSM auto near / LiSPSM auto z_f only]  ->
//   shadow setup (GL-free math: B, SSM/PSM/LiSPSM matrix)  ->  caster culling against B  ->
//   shadow pass (depth map; skipped when its key is unchanged)  ->
//   [shadow-term pass + N blur passes, only when N > 0]  ->  forward pass
// What a frame skips when it does not need it is switchable in Settings::skip (docs/design.md).
#include "resources/cascade_maps.h"
#include "culling/instance_culling.h"
#include "frame/caster_model.h"
#include "frame/frame_setup.h"
#include "frame/frame_stats.h"
#include "gl/program.h"
#include "resources/gpu_scene.h"
#include "gl/gpu_timer.h"
#include "passes/cluster_draw_list.h"
#include "passes/material_programs.h"
#include "resources/msaa_target.h"
#include "resources/measure_pass.h"
#include "resources/shadow_resources.h"
#include "passes/visible_depth.h"

#include <functional>
#include <memory>
#include <string>

namespace shadowlab {

struct Viewport {
    GLuint framebuffer = 0;  // 0 = the window's
    int x = 0, y = 0, width = 0, height = 0;
};

class Renderer {
public:
    // nullptr and a message when the shaders do not build on this GL.
    static std::unique_ptr<Renderer> create(std::string& error);

    // Uploads the scene (geometry and textures once). `streamTextures`: the textures follow over
    // the next frames through streamTextures() (the viewer; headless renders upload them at once).
    // `timings` (optional) gets the build steps (clusters, BVH, caster model) and the upload added.
    void setScene(const Scene& scene, bool streamTextures = false, LoadTimings* timings = nullptr);
    // Uploads deferred textures for about `budgetMs` (at least one); a scene change for the map
    // reuse (masked textures shape the shadow map). The number still to come.
    std::size_t streamTextures(double budgetMs);
    // After node transforms changed (animation): new instance matrices and deformed vertices of
    // the instances that moved; shadow maps stay valid unless one of their casters moved.
    void updateInstances(const Scene& scene);

    // Draws one view of `scene` with `settings` into `viewport`. `seconds` drives the animated sun.
    FrameStats render(const Scene& scene, const Settings& settings, double seconds, const Viewport& viewport);

    // render() until the frame no longer depends on a readback in flight (FrameStats::
    // needsAnotherFrame; at most three frames): what a headless single picture must show.
    FrameStats renderSettled(const Scene& scene, const Settings& settings, double seconds, const Viewport& viewport);

    // Does a triangle facing the light come out counter-clockwise in the shadow map? Warps may
    // mirror the map (PSM's post-perspective space, reflected fits), which swaps what GL culls as
    // front and back; back-face rendering (thesis 5.1) must cull the faces that face the light.
    static bool lightFacingIsCounterClockwise(const glm::dmat4& worldToShadowClip, const LightFrame& light,
                                              const Aabb& body);

    // render() into `viewport`, then the measurement pass of the same frame (renderer_measure.cpp):
    // the float values of the accuracy instruments, read back into `out`. With `shadowCamera`, the
    // shadows are set up for that camera while the image is drawn from settings.camera, so two
    // frames drawn from one camera differ only in their maps (temporal stability, accuracy.h).
    FrameStats renderMeasured(const Scene& scene, const Settings& settings, double seconds, const Viewport& viewport,
                              MeasureFrame& out, const CameraSettings* shadowCamera = nullptr);

    // Waits for the GPU timings of the frames in flight (headless renders report real GPU ms) and
    // fills them into lastFrameStats().
    void resolveTimings();
    // Timer queries issued and not yet read back (the viewer may poll for them without drawing).
    bool timingsPending() const;
    // A visible-depth readback is in flight: FrameStats::needsAnotherFrame said so.
    bool readbackPending() const { return visibleDepth_.pending(); }
    // The stats of the last render() call, with GPU times filled in by resolveTimings().
    const FrameStats& lastFrameStats() const { return lastStats_; }

    // The last shadow map (depth texture), for insets; 0 before the first shadowed frame.
    GLuint shadowMapTexture() const { return shadowMaps_.empty() ? 0 : shadowMap().texture(); }
    const ShadowSetup& lastShadowSetup() const { return lastSetup_; }
    // Cascaded shadow maps (settings.csm) of the last frame: every split's eye-depth range, its
    // ShadowSetup (B_i, V_i, ... in setup.diagnostics when an overlay asked for polygons) and
    // texel size; no splits when the last frame used one map. lastShadowSetup() is then the first
    // split that sees something. The maps: one layer per split of a GL_TEXTURE_2D_ARRAY (depth,
    // compare mode on; 0 when csm is off).
    const CascadeSetup& lastCascadeSetup() const { return lastCascades_; }
    GLuint cascadeMapTexture() const { return cascadeMaps().texture(); }
    int cascadeMapLayers() const { return cascadeMaps().layers(); }
    const GpuScene* gpuScene() const { return gpuScene_.get(); }
    // The caster model of the last frame, with the backdrops found on load and the notices (which
    // instance was excluded and how to change it) for the viewer and `render`.
    const CasterChoice& lastCasterChoice() const { return casterChoice_; }
    const std::vector<std::size_t>& backdrops() const { return backdrops_; }

private:
    Renderer() = default;
    struct Frame;
    // Eye distances of the nearest and farthest visible geometry (visible_depth.h).
    VisibleDepthRange visibleDepthRange(const Frame& frame, FrameStats& stats, bool waitOnCut = false);
    void cullView(Frame& frame, FrameStats& stats) const;
    void cullCasters(Frame& frame, FrameStats& stats) const;
    ShadowMapKey shadowMapKey(const Frame& frame) const;
    void shadowPass(const Frame& frame, FrameStats& stats);
    // The depth of frame.casters through frame.worldToShadowClip into a square depth target.
    void drawShadowDepth(const Frame& frame, GLuint framebuffer, int size, PassCounts& counts);
    // Cascaded shadow maps (cascade_pass.cpp): per-split setups and caster culling, one shadow
    // pass per split into its layer, and the lookup's uniforms.
    void setupCascades(Frame& frame, FrameStats& stats);
    void cascadeShadowPass(const Frame& frame, FrameStats& stats);
    void setCascadeUniforms(const gl::Program& program, const Frame& frame) const;
    MaterialPrograms& forwardFor(const Frame& frame);
    void shadowTermPass(const Frame& frame, FrameStats& stats);
    void blurPasses(const Frame& frame, FrameStats& stats);
    void forwardPass(const Frame& frame, FrameStats& stats);
    void measurePass(const Frame& frame, FrameStats& stats);
    void setLightingUniforms(const gl::Program& program, const Frame& frame, bool useBlurredTerm) const;
    enum class Surfaces { All, OpaqueAndMasked, Blended };
    // The program of a material in this pass (scene_draw.cpp).
    using ProgramFor = std::function<DrawProgram(const GpuMaterial&)>;
    // The material variants of `programs` (skip.shaderVariants), each given the pass's uniforms by
    // `setup` the first time a draw uses it.
    static ProgramFor passPrograms(MaterialPrograms& programs, bool depthOnly, const Settings& settings,
                                   std::function<void(const gl::Program&)> setup);
    // `sides`: which faces of single- and double-sided materials are drawn (its faces only; the
    // shadow pass hands the frame's caster model, the camera's passes kCameraSides).
    void drawScene(const ProgramFor& programFor, const Frame& frame, const InstanceList& instances,
                   const CasterModel& sides, PassCounts& counts, Surfaces surfaces = Surfaces::All,
                   bool targetMirrored = false) const;
    // Every material with the one `program` (the measurement pass).
    void drawScene(const gl::Program& program, const Frame& frame, const InstanceList& instances,
                   const CasterModel& sides, PassCounts& counts, Surfaces surfaces = Surfaces::All,
                   bool targetMirrored = false) const;
    // What the camera sees: single-sided materials from the front (glTF 2.0 3.9.5), double-sided both.
    inline static const CasterModel kCameraSides{CasterFaces::Front, CasterFaces::Both, {}};

    MaterialPrograms forward_;
    MaterialPrograms forwardCascaded_;    // forward.frag with CASCADES: the split picked by eye depth
    MaterialPrograms shadowDepth_;        // hyperbolic depth (the warp's own)
    MaterialPrograms shadowDepthLinear_;  // linear light-space depth written per fragment
    gl::Program blur_;
    gl::VertexArray emptyVao_;  // fullscreen triangles read no attributes
    std::unique_ptr<GpuScene> gpuScene_;
    mutable ClusterDrawList clusterDraws_;  // a pass's indirect draws of clustered meshes (scratch)
    mutable InstanceList wholeScratch_;     // a pass's instances of meshes drawn whole (scratch)
    InstanceCuller culler_;
    const Scene* scene_ = nullptr;    // the scene uploaded last
    std::vector<std::size_t> backdrops_;  // detectBackdrops of the scene uploaded last
    CasterChoice casterChoice_;           // the last frame's (lastCasterChoice)
    std::uint64_t sceneLoads_ = 0;    // bumped by setScene
    std::uint64_t sceneVersion_ = 0;  // bumped by setScene, streamed textures and instances that moved
    std::uint64_t contentVersion_ = 0;  // sceneVersion_ of the last geometry or texture upload
    std::vector<std::uint64_t> instanceMoved_;     // per instance: sceneVersion_ when it last moved
    std::vector<std::uint32_t> changedInstances_;  // scratch of updateInstances
    std::uint64_t castersMoved(const InstanceList& casters) const;  // latest instanceMoved_ among them
    // The map of the last shadowed frame, out of one per compared view (selectShadowMap).
    ShadowMap& shadowMap() { return shadowMaps_[currentMap_]; }
    const ShadowMap& shadowMap() const { return shadowMaps_[currentMap_]; }
    std::size_t selectShadowMap(const ShadowMapKey& key, int views);
    std::vector<ShadowMap> shadowMaps_{1};
    std::vector<std::uint64_t> mapLastUse_{0};
    std::uint64_t mapUseClock_ = 0;
    std::size_t currentMap_ = 0;
    // The cascade layers of the last cascaded frame, out of one array per compared view, as the
    // one-map pool (selectCascadeMaps, cascade_pass.cpp).
    CascadeMaps& cascadeMaps() { return cascadePool_[currentCascades_]; }
    const CascadeMaps& cascadeMaps() const { return cascadePool_[currentCascades_]; }
    std::size_t selectCascadeMaps(const std::vector<ShadowMapKey>& layerKeys, int views);
    std::vector<CascadeMaps> cascadePool_{1};
    std::vector<std::uint64_t> cascadeLastUse_{0};
    std::size_t currentCascades_ = 0;
    CascadeSetup lastCascades_;  // lastCascadeSetup()
    ShadowTermTargets termTargets_;
    VisibleDepthPrePass visibleDepth_;  // PSM auto near / LiSPSM auto z_f
    MsaaTarget msaa_;  // the forward pass's multisampled target (display.msaaSamples > 1)
    ShadowSetup lastSetup_{};
    gl::Program measure_;  // built on first use
    gl::Program measureCascaded_;  // measure.frag with CASCADES, built on first use
    MeasureTargets measureTargets_;
    struct MeasureRequest {
        MeasureTargets* targets = nullptr;  // set only inside renderMeasured
        MeasureFrame* out = nullptr;
    } measureRequest_;
    const CameraSettings* shadowCameraRequest_ = nullptr;  // set only inside renderMeasured
    GpuTimer shadowTimer_, termTimer_, blurTimer_, forwardTimer_;
    FrameStats lastStats_;
    std::vector<std::pair<std::size_t, GpuTimer*>> timedPasses_;
    std::vector<std::pair<std::size_t, GpuTimer*>> lastTimedPasses_;  // pass index in lastStats_, its timer
};

}  // namespace shadowlab
