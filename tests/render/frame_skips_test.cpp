// Every skip (shadow-map reuse, BVH culling, async depth readback, grouped draws, shader
// variants) changes the work, never the picture. The forest's views and Sponza are rendered with
// every skip on and with every skip off and must give identical images; small images keep this
// fast on llvmpipe.
#include "render_helpers.h"
#include "scenes/gltf_loader.h"
#include "test_scenes.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <map>
#include <memory>

namespace shadowlab::test {
namespace {

Settings withSkips(Settings s, bool on) {
    s.skip.reuseShadowMap = on;
    s.skip.hierarchicalCulling = on;
    s.skip.asyncDepthReadback = on;
    s.skip.groupedDraws = on;
    s.skip.shaderVariants = on;
    s.skip.clusterCulling = on;
    return s;
}

class FrameSkips : public RenderTest {
protected:
    static const Scene* loaded(const std::string& file) {
        static std::map<std::string, std::unique_ptr<Scene>> cache;
        auto it = cache.find(file);
        if (it == cache.end()) {
            LoadResult r = loadScene(file);
            EXPECT_TRUE(r.ok()) << r.error;
            it = cache.emplace(file, r.ok() ? std::make_unique<Scene>(std::move(*r.scene)) : nullptr).first;
        }
        return it->second.get();
    }

    // The image a view settles on: a second frame of the same view (the async depth readback
    // measures in the first). With skips on, that frame also reuses the first frame's map.
    RgbaImage settled(const Scene& scene, const Settings& s, FrameStats* stats = nullptr) {
        render(scene, s);
        return render(scene, s, stats);
    }

    // One frame only (render() settles over the async readback): the frame right after a change.
    FrameStats firstFrame(const Scene& scene, const Settings& s) {
        return renderer_->render(scene, s, 0.0, Viewport{target_->framebuffer(), 0, 0, kWidth, kHeight});
    }

    // Renders every (view, method) with skips on and off; returns how many maps were reused.
    int expectSameImages(const Scene& scene, const std::vector<Settings>& views) {
        int reused = 0;
        for (std::size_t v = 0; v < views.size(); ++v) {
            FrameStats on, off;
            const RgbaImage a = settled(scene, withSkips(views[v], true), &on);
            const RgbaImage b = settled(scene, withSkips(views[v], false), &off);
            EXPECT_EQ(a.pixels, b.pixels) << "view " << v << " (" << methodName(views[v].method) << ")";
            EXPECT_EQ(on.instancesVisible, off.instancesVisible) << "view " << v;
            EXPECT_EQ(on.castersDrawn, off.castersDrawn) << "view " << v;
            EXPECT_FALSE(off.shadowMapReused);
            reused += on.shadowMapReused ? 1 : 0;
        }
        return reused;
    }
};

TEST_F(FrameSkips, ForestViewsLookTheSameWithEverySkipOnAndOff) {
    const Scene* forest = loaded(SHADOWLAB_BUILD_SCENES "/forest.glb");
    ASSERT_TRUE(forest);
    std::vector<Settings> views;
    for (std::size_t c = 0; c < forest->cameras.size(); ++c) {
        Settings s;
        s.camera = cameraFromScene(forest->cameras[c], s.camera);
        s.shadowMapSize = 512;
        s.method = std::array{ShadowMethod::Lispsm, ShadowMethod::Psm, ShadowMethod::SsmFocused}[c % 3];
        if (c == 1) s.filter.blurIterations = 1;  // the shadow-term pass and its culling too
        views.push_back(s);
    }
    ASSERT_GE(views.size(), 3u);
    EXPECT_EQ(expectSameImages(*forest, views), int(views.size()));  // every settled frame reused its map
}

TEST_F(FrameSkips, SponzaLooksTheSameWithEverySkipOnAndOff) {
    const Scene* sponza = loaded(SHADOWLAB_SHARED_SCENES "/Sponza/Sponza.gltf");
    ASSERT_TRUE(sponza);
    std::vector<Settings> views;
    for (ShadowMethod m : {ShadowMethod::Lispsm}) {  // PSM and SSM: the forest views
        Settings s;
        if (!sponza->cameras.empty()) s.camera = cameraFromScene(sponza->cameras.front(), s.camera);
        s.shadowMapSize = 512;
        s.method = m;
        views.push_back(s);
    }
    expectSameImages(*sponza, views);
}

TEST_F(FrameSkips, PostProcessSettingsReuseTheMapAndWhatItDependsOnRendersItAgain) {
    Scene scene = planeBoxScene();
    Settings s = lookAt({6.0, 5.0, 8.0}, {0.0, 0.5, 0.0});
    s.method = ShadowMethod::Lispsm;
    s.filter.blurIterations = 1;
    FrameStats stats;
    settled(scene, s, &stats);
    EXPECT_TRUE(stats.shadowMapReused);
    auto reusedAfter = [&](auto change) {
        Settings changed = s;
        change(changed);
        const bool reused = firstFrame(scene, changed).shadowMapReused;
        settled(scene, s);  // back to the base view (and its map)
        return reused;
    };
    EXPECT_TRUE(reusedAfter([](Settings& c) { c.filter.blurStrength = 2.5; }));
    EXPECT_TRUE(reusedAfter([](Settings& c) { c.filter.blurIterations = 3; }));
    EXPECT_TRUE(reusedAfter([](Settings& c) { c.filter.filter = ShadowFilter::Pcf4x4; }));
    EXPECT_TRUE(reusedAfter([](Settings& c) { c.viewMode = ViewMode::ShadowTermOnly; }));
    EXPECT_TRUE(reusedAfter([](Settings& c) { c.overlays.shadowMapInset = true; }));
    EXPECT_TRUE(reusedAfter([](Settings& c) { c.bias.constant = 0.01; }));
    EXPECT_FALSE(reusedAfter([](Settings& c) { c.light.source = LightSource::Sun, c.light.azimuthDeg += 5.0; }));
    EXPECT_FALSE(reusedAfter([](Settings& c) { c.camera.yawDeg += 2.0; }));  // LiSPSM follows the view
    EXPECT_FALSE(reusedAfter([](Settings& c) { c.shadowMapSize = 1024; }));
    // The default adaptive bias acts in the lookup only; the slope-scale offset is in the map.
    EXPECT_TRUE(reusedAfter([](Settings& c) { c.bias.adaptiveMargin = 0.5; }));
    EXPECT_FALSE(reusedAfter([](Settings& c) { c.bias.mode = DepthOffset::SlopeScale, c.bias.slopeFactor = 3.0; }));
    EXPECT_FALSE(reusedAfter([](Settings& c) { c.casters.singleSided = CasterFaces::Back; }));
    EXPECT_FALSE(reusedAfter([](Settings& c) { c.skip.reuseShadowMap = false; }));
    // Moved casters (animation): the same settings, new instance matrices.
    MeshInstance& box = scene.instances[1];
    box.world = glm::translate(box.world, glm::dvec3(0.5, 0.0, 0.0));
    box.worldBounds = scene.meshes[1].primitives[0].bounds.transformed(box.world);
    renderer_->updateInstances(scene);
    EXPECT_FALSE(firstFrame(scene, s).shadowMapReused);
}

// Cascades: each layer is reused on its own. Skips on and off give the same pixels for
// every per-split parameterisation; a still camera reuses every layer; a moved light re-renders
// them all; a camera move that changes only the far splits keeps the near ones (stable splits:
// their texel grid is fixed to the world, so a move along the view axis within one texel of the
// near layers' grid keeps those).
TEST_F(FrameSkips, CascadeLayersAreReusedWhileTheirSplitStays) {
    const Scene* forest = loaded(SHADOWLAB_BUILD_SCENES "/forest.glb");
    ASSERT_TRUE(forest);
    std::vector<Settings> views;
    for (SplitParameterization p : {SplitParameterization::Ssm, SplitParameterization::StableSsm,
                                    SplitParameterization::Lispsm}) {
        Settings s;
        s.camera = cameraFromScene(forest->cameras.front(), s.camera);
        s.shadowMapSize = 256;
        s.csm.enabled = true;
        s.csm.perSplit = p;
        if (p == SplitParameterization::Lispsm) s.filter.blurIterations = 1;
        views.push_back(s);
    }
    EXPECT_EQ(expectSameImages(*forest, views), int(views.size()));

    Settings s = withSkips(views[1], true);
    FrameStats stats;
    settled(*forest, s, &stats);
    EXPECT_TRUE(stats.shadowMapReused);
    EXPECT_EQ(stats.cascadeLayersReused, s.csm.splits);
    EXPECT_EQ(stats.shadowPass.drawCalls, 0u);
    Settings moved = s;
    moved.light.source = LightSource::Sun;
    moved.light.azimuthDeg += 5.0;
    moved.skip.asyncDepthReadback = false;  // this frame's depth range, no estimate
    stats = firstFrame(*forest, moved);
    EXPECT_FALSE(stats.shadowMapReused);
    EXPECT_EQ(stats.cascadeLayersReused, 0);
    EXPECT_GT(stats.shadowPass.drawCalls, 0u);
    stats = firstFrame(*forest, moved);  // and still again: all reused
    EXPECT_EQ(stats.cascadeLayersReused, moved.csm.splits);
}

// Stable cascades under small camera steps (shimmering): the map's grid is fixed to the
// world and its split ranges and depth rows are snapped, so a 1 cm sideways step leaves most
// frames' layers exactly as they were (the reuse key matches: same matrix, depth range and
// casters). The focused splits re-fit to every step (the control).
TEST_F(FrameSkips, StableCascadesKeepTheirLayersUnderCentimetreSteps) {
    const Scene* forest = loaded(SHADOWLAB_BUILD_SCENES "/forest.glb");
    ASSERT_TRUE(forest);
    auto reusedFrames = [&](SplitParameterization perSplit) {
        Settings s;
        s.camera = cameraFromScene(forest->cameras.front(), s.camera);
        s.shadowMapSize = 256;
        s.csm.enabled = true;
        s.csm.perSplit = perSplit;
        s.skip.asyncDepthReadback = false;  // each frame's own visible depth, as the temporal instrument
        render(*forest, s);                 // creates renderer and target
        int reused = 0;
        for (int step = 1; step <= 10; ++step) {
            s.camera.position.x += 0.01;
            reused += firstFrame(*forest, s).cascadeLayersReused == s.csm.splits ? 1 : 0;
        }
        return reused;
    };
    EXPECT_GE(reusedFrames(SplitParameterization::StableSsm), 7);
    EXPECT_EQ(reusedFrames(SplitParameterization::Ssm), 0);
}

TEST_F(FrameSkips, EachViewOfASplitCompareKeepsItsOwnMap) {
    const Scene scene = planeBoxScene();
    Settings s = lookAt({6.0, 5.0, 8.0}, {0.0, 0.5, 0.0});
    s.compare.count = 3;
    render(scene, s);  // creates renderer and target
    const ShadowMethod methods[3] = {ShadowMethod::SsmFocused, ShadowMethod::Psm, ShadowMethod::Lispsm};
    auto view = [&](ShadowMethod m) {
        Settings v = s;
        v.method = m;
        return v;
    };
    // Viewer frames: each view once per frame. The first frames evict each other's maps (PSM and
    // LiSPSM start on estimated visible depths); from the third frame on every view reuses its own.
    for (int frame = 0; frame < 2; ++frame)
        for (ShadowMethod m : methods) firstFrame(scene, view(m));
    for (ShadowMethod m : methods) EXPECT_TRUE(firstFrame(scene, view(m)).shadowMapReused) << methodName(m);
    s.compare.count = 1;  // one view again: one map, re-rendered as the methods alternate
    s.method = ShadowMethod::SsmFocused;
    firstFrame(scene, s);
    s.method = ShadowMethod::Lispsm;
    EXPECT_FALSE(firstFrame(scene, s).shadowMapReused);
}

// The same for cascades: each pane of a split compare keeps its own layers (one array per view).
TEST_F(FrameSkips, EachCascadedViewOfASplitCompareKeepsItsOwnLayers) {
    const Scene scene = planeBoxScene();
    Settings s = lookAt({6.0, 5.0, 8.0}, {0.0, 0.5, 0.0});
    s.shadowMapSize = 256;
    s.compare.count = 3;
    s.csm.enabled = true;
    render(scene, s);  // creates renderer and target
    const SplitParameterization perSplit[3] = {SplitParameterization::Ssm, SplitParameterization::StableSsm,
                                               SplitParameterization::Lispsm};
    auto view = [&](SplitParameterization p) {
        Settings v = s;
        v.csm.perSplit = p;
        return v;
    };
    for (int frame = 0; frame < 2; ++frame)
        for (SplitParameterization p : perSplit) firstFrame(scene, view(p));
    for (SplitParameterization p : perSplit) {
        const FrameStats f = firstFrame(scene, view(p));
        EXPECT_TRUE(f.shadowMapReused) << splitParameterizationName(p);
        EXPECT_EQ(f.cascadeLayersReused, s.csm.splits) << splitParameterizationName(p);
    }
    s.compare.count = 1;  // one view: one array, re-rendered as the parameterisations alternate
    firstFrame(scene, view(SplitParameterization::Ssm));
    EXPECT_EQ(firstFrame(scene, view(SplitParameterization::Lispsm)).cascadeLayersReused, 0);
}

TEST_F(FrameSkips, VisibleDepthArrivesOneFrameLateAndIsKeptWhileTheViewStays) {
    const Scene scene = planeBoxScene();
    Settings s = lookAt({6.0, 5.0, 8.0}, {0.0, 0.5, 0.0});
    s.method = ShadowMethod::Psm;  // auto near on
    s.psm.guard = false;           // the near plane alone does not wait on a cut
    render(scene, s);              // creates renderer and target
    Settings other = s;
    other.camera.yawDeg += 40.0;  // a cut
    FrameStats f = firstFrame(scene, other);
    EXPECT_EQ(f.visibleDepth, VisibleDepthSource::Fallback);
    EXPECT_TRUE(f.needsAnotherFrame);
    EXPECT_GT(f.depthPrePass.drawCalls, 0u);
    f = firstFrame(scene, other);
    EXPECT_EQ(f.visibleDepth, VisibleDepthSource::Cached);  // the readback of the frame before
    EXPECT_FALSE(f.needsAnotherFrame);
    EXPECT_EQ(f.depthPrePass.drawCalls, 0u);  // nothing changed: no pre-pass at all
    other.camera.position.x += 0.05;           // a small move: last frame's range, widened
    f = firstFrame(scene, other);
    EXPECT_EQ(f.visibleDepth, VisibleDepthSource::PreviousFrame);
    EXPECT_TRUE(f.needsAnotherFrame);
    other.skip.asyncDepthReadback = false;
    EXPECT_EQ(firstFrame(scene, other).visibleDepth, VisibleDepthSource::Measured);
    other.psm.autoNear = false;
    other.psm.guard = true;  // the guard alone still needs the receivers
    EXPECT_EQ(firstFrame(scene, other).visibleDepth, VisibleDepthSource::Measured);
    other.psm.guard = false;
    f = firstFrame(scene, other);
    EXPECT_EQ(f.visibleDepth, VisibleDepthSource::NotNeeded);
    EXPECT_EQ(f.depthPrePass.drawCalls, 0u);
    EXPECT_FALSE(f.needsAnotherFrame);
    // PSM's guard judges at the receivers: on a cut the frame waits for its own measurement.
    Settings guarded = other;
    guarded.skip.asyncDepthReadback = true;
    guarded.psm.guard = true;
    guarded.camera.yawDeg -= 80.0;
    f = firstFrame(scene, guarded);
    EXPECT_EQ(f.visibleDepth, VisibleDepthSource::MeasuredOnCut);
    EXPECT_FALSE(f.needsAnotherFrame);
    EXPECT_GT(f.depthPrePass.drawCalls, 0u);
    EXPECT_EQ(firstFrame(scene, guarded).visibleDepth, VisibleDepthSource::Cached);
}

TEST_F(FrameSkips, StatsJsonCarriesTheFiguresOfTheFrame) {
    const Scene scene = planeBoxScene();
    Settings s = lookAt({6.0, 5.0, 8.0}, {0.0, 0.5, 0.0});
    FrameStats stats;
    settled(scene, s, &stats);
    const nlohmann::json j = nlohmann::json::parse(frameStatsJson(stats));
    EXPECT_EQ(j["instances"], scene.instances.size());
    EXPECT_EQ(j["shadowMapReused"], true);
    EXPECT_EQ(j["shadowPass"]["drawCalls"], 0);  // reused: nothing drawn into the map
    EXPECT_GT(j["forwardPass"]["triangles"].get<int>(), 0);
    EXPECT_EQ(j["castersDrawn"].get<std::size_t>() + j["castersCulled"].get<std::size_t>(), scene.instances.size());
    EXPECT_TRUE(j["passes"].is_array());
    EXPECT_TRUE(j.contains("cullingCpuMs"));
    // The setup's readouts: which warp ran, with n as "inf" where it is the uniform map.
    const nlohmann::json& setup = j["shadowSetup"];
    EXPECT_EQ(setup["method"], methodName(stats.shadow.method));
    EXPECT_EQ(setup["warpSamples"], stats.shadow.warpSamples);
    EXPECT_DOUBLE_EQ(setup["imageCheckLoss"].get<double>(), stats.shadow.imageCheckLoss);
    if (std::isfinite(stats.shadow.nUsed)) {
        EXPECT_DOUBLE_EQ(setup["nUsed"].get<double>(), stats.shadow.nUsed);
    } else {
        EXPECT_EQ(setup["nUsed"], "inf");
    }
}

}  // namespace
}  // namespace shadowlab::test
