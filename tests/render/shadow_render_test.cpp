// Shadows through the whole pipeline (math -> shadow pass -> lookup), checked against ray casts:
// a ground point whose ray towards the light hits the box must be dark, one whose ray misses must
// be lit, for SSM, PSM and LiSPSM and lights from the front, the side and behind the camera.
#include "render_helpers.h"
#include "test_scenes.h"

#include <glm/gtc/constants.hpp>

namespace shadowlab::test {
namespace {

const glm::dvec3 kBoxLo{-1, 0, -1}, kBoxHi{1, 2, 1};
constexpr double kGroundHalf = 10.0;

// Light directions (the way light travels) with the camera at (0, 9, 11) looking at the origin.
glm::dvec3 fromFront() { return glm::normalize(glm::dvec3(0.2, -0.7, 1.0)); }   // towards the camera
glm::dvec3 fromSide() { return glm::normalize(glm::dvec3(1.0, -0.8, 0.1)); }
glm::dvec3 fromBehind() { return glm::normalize(glm::dvec3(-0.7, -0.6, -0.45)); }  // PSM's hard case

Settings shadowView(ShadowMethod method) {
    Settings s = lookAt({0.0, 9.0, 11.0}, {0.0, 0.0, 0.0});
    s.method = method;
    s.viewMode = ViewMode::ShadowTermOnly;  // lit 0.9, shadowed 0.18: no shading to confuse the test
    s.shadowMapSize = 1024;
    s.filter.filter = ShadowFilter::Nearest;
    return s;
}

enum class Truth { Lit, Shadow, Unknown };

// Ground truth for the pixel: the ground point it sees, if any, and whether it is robustly lit
// (its shadow ray misses the box grown by `margin`) or robustly shadowed (it hits the box shrunk by it).
Truth groundTruth(const Settings& s, glm::dvec3 light, int x, int y, double margin) {
    glm::dvec3 o, d;
    pixelRay(s, RenderTest::kWidth, RenderTest::kHeight, x, y, o, d);
    if (d.y >= -1e-6) return Truth::Unknown;
    const double t = -o.y / d.y;
    const glm::dvec3 p = o + d * t;
    if (std::abs(p.x) > kGroundHalf - margin || std::abs(p.z) > kGroundHalf - margin) return Truth::Unknown;
    if (rayHitsBox(o, d, kBoxLo - margin, kBoxHi + margin, 0.0, t)) return Truth::Unknown;  // box or its edge in front
    if (!rayHitsBox(p, -light, kBoxLo - margin, kBoxHi + margin)) return Truth::Lit;
    if (rayHitsBox(p, -light, kBoxLo + margin, kBoxHi - margin)) return Truth::Shadow;
    return Truth::Unknown;
}

struct Classification {
    int lit = 0, litButDark = 0;
    int shadow = 0, shadowButLit = 0;
};

Classification classify(const RgbaImage& image, const Settings& s, glm::dvec3 light, double margin) {
    Classification c;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const Truth truth = groundTruth(s, light, x, y, margin);
            const bool dark = luminance(image.at(x, y)) < 180.0;  // between 118 (shadow) and 243 (lit)
            if (truth == Truth::Lit) {
                ++c.lit;
                c.litButDark += dark;
            } else if (truth == Truth::Shadow) {
                ++c.shadow;
                c.shadowButLit += !dark;
            }
        }
    return c;
}

struct Case {
    ShadowMethod method;
    const char* lightName;
    glm::dvec3 (*light)();
};

class ShadowRender : public RenderTest, public ::testing::WithParamInterface<Case> {};

TEST_P(ShadowRender, GeometricShadowIsDarkAndOpenGroundIsLit) {
    const Case c = GetParam();
    const glm::dvec3 light = c.light();
    const Scene scene = planeBoxScene(light);
    Settings s = shadowView(c.method);
    FrameStats stats;
    const RgbaImage image = render(scene, s, &stats);
    const Classification k = classify(image, s, light, 0.25);
    ASSERT_GT(k.shadow, 60) << "the box's shadow must be in view";
    ASSERT_GT(k.lit, 1000);
    // Tolerances: 2 % of pixels, for texel-sized steps along the shadow outline under SSM focusing.
    EXPECT_LT(k.shadowButLit, k.shadow * 2 / 100) << c.lightName << ": shadowed ground rendered lit";
    EXPECT_LT(k.litButDark, k.lit * 2 / 100) << c.lightName << ": lit ground rendered dark (acne or wrong map)";
    EXPECT_GT(stats.castersDrawn, 0u);
    EXPECT_EQ(stats.shadowMapSize, 1024);
}

INSTANTIATE_TEST_SUITE_P(
    MethodsAndLights, ShadowRender,
    ::testing::Values(Case{ShadowMethod::SsmFocused, "front", fromFront}, Case{ShadowMethod::SsmFocused, "side", fromSide},
                      Case{ShadowMethod::SsmFocused, "behind", fromBehind}, Case{ShadowMethod::Psm, "front", fromFront},
                      Case{ShadowMethod::Psm, "side", fromSide}, Case{ShadowMethod::Psm, "behind", fromBehind},
                      Case{ShadowMethod::Lispsm, "front", fromFront}, Case{ShadowMethod::Lispsm, "side", fromSide},
                      Case{ShadowMethod::Lispsm, "behind", fromBehind},
                      Case{ShadowMethod::SsmUnfocused, "side", fromSide}),
    [](const ::testing::TestParamInfo<Case>& info) {
        std::string name = std::string(methodName(info.param.method)) + "_" + info.param.lightName;
        std::replace(name.begin(), name.end(), '-', '_');
        return name;
    });

// PSM with a tiny near plane (0.01, as Sponza's cameras have): post-perspective space squeezes
// everything beyond a few metres into a sliver; the auto near plane (Stamminger & Drettakis 4.2, 6:
// the nearest visible depth from a depth pre-pass) restores correct shadows.
TEST_F(ShadowRender, PsmWithATinyNearPlaneStillShadowsCorrectly) {
    for (auto light : {fromFront, fromSide}) {
        const Scene scene = planeBoxScene(light());
        // Inside the scene bounds (S reaches above the eye), so B reaches the near plane too.
        Settings s = lookAt({0.0, 1.5, 9.0}, {0.0, 0.3, 0.0});
        s.method = ShadowMethod::Psm;
        s.viewMode = ViewMode::ShadowTermOnly;
        s.shadowMapSize = 1024;
        s.filter.filter = ShadowFilter::Nearest;
        s.camera.nearPlane = 0.01;
        s.psm.autoNear = true;  // with false, 317 of ~400 shadowed ground pixels came out lit
        FrameStats stats;
        const Classification k = classify(render(scene, s, &stats), s, light(), 0.25);
        ASSERT_GT(k.shadow, 60);
        EXPECT_LT(k.shadowButLit, k.shadow * 2 / 100);
        EXPECT_LT(k.litButDark, k.lit * 2 / 100);
        EXPECT_GT(stats.shadow.psmNear, 1.0) << "the near plane was pushed to the visible geometry";
    }
}

// The image check (math/image_check.h) runs in the renderer under a sun too: the pre-pass hands the
// fine grid for it, the diagnostics count its points, and the setting switches it off.
TEST_F(ShadowRender, SunWarpsAreCheckedOverThePrePassFineGrid) {
    const Scene scene = planeBoxScene(fromSide());
    for (const ShadowMethod method : {ShadowMethod::Lispsm, ShadowMethod::Psm}) {
        Settings s = lookAt({0.0, 1.5, 9.0}, {0.0, 0.3, 0.0});
        s.method = method;
        s.shadowMapSize = 512;
        FrameStats stats;
        render(scene, s, &stats);
        SCOPED_TRACE(methodName(method));
        // Both warps beat SSM on this ground view (loss 0.34 and 0.28 over ~400 points), so both are kept.
        EXPECT_TRUE(stats.shadow.fallback.empty()) << stats.shadow.fallback;
        if (method == ShadowMethod::Lispsm) {
            EXPECT_GT(stats.shadow.warp, 0.0);
        }
        EXPECT_GT(stats.shadow.imageCheckSamples, 100) << "the fine grid's receivers in the light";
        EXPECT_GT(stats.shadow.imageCheckLoss, 0.0);
        EXPECT_LT(stats.shadow.imageCheckLoss, 1.0);
        if (method != ShadowMethod::Lispsm) continue;
        s.lispsm.imageCheck = false;
        render(scene, s, &stats);
        EXPECT_EQ(stats.shadow.imageCheckSamples, 0);
    }
}

// A spot light (thesis 9.2.3: L_r, eq. 8.13 for n): the box's shadow under the cone is dark for
// every method; the ground truth casts rays towards the light's position.
class SpotShadowRender : public RenderTest, public ::testing::WithParamInterface<ShadowMethod> {};

TEST_P(SpotShadowRender, ShadowUnderTheConeIsDarkAndOpenGroundIsLit) {
    const glm::dvec3 lightPos{5.0, 7.0, 3.0};
    Scene scene = planeBoxScene();
    Light& spot = scene.lights[0];
    spot.type = LightType::Spot;
    spot.position = lightPos;
    spot.direction = glm::normalize(glm::dvec3(-1.0, 0.0, -1.0) - lightPos);
    spot.outerConeAngle = float(glm::radians(40.0));
    spot.innerConeAngle = float(glm::radians(30.0));
    Settings s = shadowView(GetParam());
    const RgbaImage image = render(scene, s);
    int lit = 0, litButDark = 0, shadow = 0, shadowButLit = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            glm::dvec3 o, d;
            pixelRay(s, kWidth, kHeight, x, y, o, d);
            if (d.y >= -1e-6) continue;
            const glm::dvec3 p = o + d * (-o.y / d.y);
            if (std::abs(p.x) > kGroundHalf - 0.3 || std::abs(p.z) > kGroundHalf - 0.3) continue;
            if (rayHitsBox(o, d, kBoxLo - 0.3, kBoxHi + 0.3, 0.0, -o.y / d.y)) continue;
            const glm::dvec3 toLight = lightPos - p;
            const double dist = glm::length(toLight);
            // Well inside the cone only: outside it the spot does not light and nothing is tested.
            if (glm::dot(-toLight / dist, glm::dvec3(spot.direction)) < std::cos(glm::radians(34.0))) continue;
            const bool dark = luminance(image.at(x, y)) < 180.0;
            if (!rayHitsBox(p, toLight / dist, kBoxLo - 0.25, kBoxHi + 0.25, 1e-6, dist)) {
                ++lit;
                litButDark += dark;
            } else if (rayHitsBox(p, toLight / dist, kBoxLo + 0.25, kBoxHi - 0.25, 1e-6, dist)) {
                ++shadow;
                shadowButLit += !dark;
            }
        }
    ASSERT_GT(shadow, 60);
    ASSERT_GT(lit, 1000);
    EXPECT_LT(shadowButLit, shadow * 2 / 100) << methodName(GetParam());
    EXPECT_LT(litButDark, lit * 2 / 100) << methodName(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Methods, SpotShadowRender,
                         ::testing::Values(ShadowMethod::SsmFocused, ShadowMethod::Psm, ShadowMethod::Lispsm),
                         [](const ::testing::TestParamInfo<ShadowMethod>& info) {
                             return std::string(methodName(info.param));
                         });

// Cascaded shadow maps (settings.csm): 4 splits of 1024^2 each, the split picked per pixel by eye
// depth; every per-split parameterization must put the box's shadow where the ray cast does.
struct CascadeCase {
    SplitParameterization perSplit;
    const char* lightName;
    glm::dvec3 (*light)();
};
class CascadeShadowRender : public RenderTest, public ::testing::WithParamInterface<CascadeCase> {};

TEST_P(CascadeShadowRender, GeometricShadowIsDarkAndOpenGroundIsLit) {
    const CascadeCase c = GetParam();
    const glm::dvec3 light = c.light();
    const Scene scene = planeBoxScene(light);
    Settings s = shadowView(ShadowMethod::SsmFocused);
    s.csm.enabled = true;
    s.csm.splits = 4;
    s.csm.lambda = 0.5;
    s.csm.perSplit = c.perSplit;
    FrameStats stats;
    const Classification k = classify(render(scene, s, &stats), s, light, 0.25);
    ASSERT_GT(k.shadow, 60) << "the box's shadow must be in view";
    ASSERT_GT(k.lit, 1000);
    EXPECT_LT(k.shadowButLit, k.shadow * 2 / 100) << c.lightName << ": shadowed ground rendered lit";
    EXPECT_LT(k.litButDark, k.lit * 2 / 100) << c.lightName << ": lit ground rendered dark";
    EXPECT_GT(stats.castersDrawn, 0u);
    EXPECT_EQ(stats.shadowMapSize, 1024);
    bool cascadePass = false;
    for (const PassStats& p : stats.passes) cascadePass |= p.name == "shadow maps (4 splits)";
    EXPECT_TRUE(cascadePass) << "one shadow pass per split";
}

INSTANTIATE_TEST_SUITE_P(
    PerSplitAndLights, CascadeShadowRender,
    ::testing::Values(CascadeCase{SplitParameterization::Ssm, "side", fromSide},
                      CascadeCase{SplitParameterization::StableSsm, "side", fromSide},
                      CascadeCase{SplitParameterization::StableSsm, "behind", fromBehind},
                      CascadeCase{SplitParameterization::Lispsm, "front", fromFront},
                      CascadeCase{SplitParameterization::Lispsm, "behind", fromBehind}),
    [](const ::testing::TestParamInfo<CascadeCase>& info) {
        return std::string(splitParameterizationName(info.param.perSplit)) + "_" + info.param.lightName;
    });

// Sample distribution cascades (csm.placement=sdsm, math/cascades_sdsm.h): splits fitted to the
// depth pre-pass's samples only still put the box's shadow where the rays do, and the settled frame
// used this view's samples (no fallback note).
TEST_F(CascadeShadowRender, SampleDistributionSplitsKeepTheShadowInPlace) {
    const Scene scene = planeBoxScene(fromSide());
    for (SplitParameterization per : {SplitParameterization::Ssm, SplitParameterization::Lispsm}) {
        Settings s = shadowView(ShadowMethod::SsmFocused);
        s.csm.enabled = true;
        s.csm.placement = SplitPlacement::Sdsm;
        s.csm.perSplit = per;
        FrameStats stats;
        const Classification k = classify(render(scene, s, &stats), s, fromSide(), 0.25);
        const std::string what = splitParameterizationName(per);
        ASSERT_GT(k.shadow, 60) << what;
        EXPECT_LT(k.shadowButLit, k.shadow * 2 / 100) << what << ": shadowed ground rendered lit";
        EXPECT_LT(k.litButDark, k.lit * 2 / 100) << what << ": lit ground rendered dark";
        EXPECT_EQ(stats.shadow.fallback.find("sdsm"), std::string::npos) << what << ": " << stats.shadow.fallback;
        const CascadeSetup& used = renderer_->lastCascadeSetup();
        EXPECT_EQ(used.placement, SplitPlacement::Sdsm) << what;
        int tight = 0;
        for (const CascadeSplit& split : used.splits) tight += split.tightBounds;
        EXPECT_GE(tight, 3) << what << ": the splits are bounded by their samples";
    }
}

// A shadow that crosses split boundaries (blend band, PCF across layers, linear depth with its
// per-split range, per-split constant offset) stays where the ray cast says.
TEST_F(CascadeShadowRender, BlendBandPcfAndLinearDepthKeepTheShadowInPlace) {
    const Scene scene = planeBoxScene(fromSide());
    Settings s = shadowView(ShadowMethod::SsmFocused);
    s.csm.enabled = true;
    s.csm.splits = 3;
    s.csm.manualSplits = {0.12, 0.2};  // split boundaries across the box's shadow
    s.csm.blendBand = 0.3;
    s.filter.filter = ShadowFilter::Pcf3x3;
    for (DepthDistribution dist : {DepthDistribution::Hyperbolic, DepthDistribution::Linear})
        for (DepthOffset mode : {DepthOffset::Constant, DepthOffset::SlopeScale}) {
            s.bias.distribution = dist;
            s.bias.mode = mode;
            const Classification k = classify(render(scene, s), s, fromSide(), 0.3);
            ASSERT_GT(k.shadow, 60);
            EXPECT_LT(k.shadowButLit, k.shadow * 3 / 100) << int(dist) << " " << int(mode);
            EXPECT_LT(k.litButDark, k.lit * 3 / 100) << int(dist) << " " << int(mode);
        }
}

// Acne (thesis 3.3, ch. 5): with no offset a grazing light on the ground shadows part of the lit
// ground; slope-scale offset (2.0 / 4.0) and back-face rendering each remove it.
class Acne : public RenderTest {
protected:
    double acneFraction(DepthOffset mode, bool backFaces, DepthDistribution distribution, double normalOffset = 0.0,
                        bool cascades = false) {
        const glm::dvec3 light = glm::normalize(glm::dvec3(1.0, -0.35, 0.3));  // low sun: strong depth slope
        const Scene scene = planeBoxScene(light);
        Settings s = shadowView(ShadowMethod::SsmFocused);
        s.bias.mode = mode;
        s.casters.singleSided = backFaces ? CasterFaces::Back : CasterFaces::Front;
        s.bias.distribution = distribution;
        s.bias.normalOffset = normalOffset;
        s.csm.enabled = cascades;
        const Classification k = classify(render(scene, s), s, light, 0.25);
        EXPECT_GT(k.lit, 1000);
        // The offset must not move the shadow off its caster (false light).
        if (normalOffset > 0.0) {
            EXPECT_LT(k.shadowButLit, k.shadow * 2 / 100) << "normal offset " << normalOffset;
        }
        return double(k.litButDark) / std::max(1, k.lit);
    }
};

TEST_F(Acne, NoBiasShowsFalseShadowSlopeScaleAndBackFacesRemoveIt) {
    const double none = acneFraction(DepthOffset::None, false, DepthDistribution::Hyperbolic);
    const double slope = acneFraction(DepthOffset::SlopeScale, false, DepthDistribution::Hyperbolic);
    const double back = acneFraction(DepthOffset::None, true, DepthDistribution::Hyperbolic);
    const double linearSlope = acneFraction(DepthOffset::SlopeScale, false, DepthDistribution::Linear);
    std::printf("acne fraction of lit ground: none %.4f, slope-scale %.4f, back faces %.4f, linear + slope %.4f\n",
                none, slope, back, linearSlope);
    EXPECT_LT(linearSlope, 0.005);
    EXPECT_GT(none, 0.05) << "without any bias a grazing light must show acne";
    EXPECT_LT(slope, 0.005);
    EXPECT_LT(back, 0.005);
}

// Normal-offset bias alone (no depth offset): moving the lookup a texel or two along the normal,
// scaled by sin(angle to the light), removes the acne of a grazing light, with one map and with
// cascades (where the texel size differs per split).
TEST_F(Acne, NormalOffsetAloneRemovesAcne) {
    for (bool cascades : {false, true}) {
        const double none = acneFraction(DepthOffset::None, false, DepthDistribution::Hyperbolic, 0.0, cascades);
        const double offset = acneFraction(DepthOffset::None, false, DepthDistribution::Hyperbolic, 2.0, cascades);
        std::printf("acne fraction of lit ground (%s): none %.4f, normal offset 2 texels %.4f\n",
                    cascades ? "csm" : "one map", none, offset);
        EXPECT_GT(none, 0.05) << "without any bias a grazing light must show acne";
        EXPECT_LT(offset, 0.005);
    }
}

// Adaptive bias (Dou et al. 2014; shaders/shadow_term.glsl): under a sun 5 degrees above the plane,
// where the ground's depth changes by 11 texels of its own size per texel, the receiver plane at
// the texel centres leaves less false shadow on the lit ground than the constant offset, with one
// map and with cascades, and keeps the box's shadow (no false light).
TEST_F(Acne, AdaptiveBiasLeavesLessFalseShadowThanConstantAtGrazingLight) {
    const glm::dvec3 light = glm::normalize(glm::dvec3(1.0, -0.0875, 0.3));  // 4.8 degrees up
    const Scene scene = planeBoxScene(light);
    for (bool cascades : {false, true})
        for (ShadowFilter filter : {ShadowFilter::Pcf2x2Hardware, ShadowFilter::Pcf3x3}) {
            double falseShadow[2] = {0.0, 0.0};
            for (DepthOffset mode : {DepthOffset::Constant, DepthOffset::Adaptive}) {
                Settings s = shadowView(ShadowMethod::Lispsm);
                s.bias.mode = mode;
                s.casters.singleSided = CasterFaces::Both;
                s.filter.filter = filter;
                s.csm.enabled = cascades;
                s.csm.perSplit = SplitParameterization::Lispsm;
                renderer_.reset();
                const Classification k = classify(render(scene, s), s, light, 0.25);
                ASSERT_GT(k.lit, 1000);
                ASSERT_GT(k.shadow, 60);
                const std::string what = std::string(cascades ? "csm" : "one map") + " filter " +
                                         std::to_string(int(filter)) + " mode " + std::to_string(int(mode));
                EXPECT_LT(k.shadowButLit, k.shadow * 2 / 100) << what << ": the box's shadow must stay";
                falseShadow[mode == DepthOffset::Adaptive] = double(k.litButDark) / k.lit;
            }
            std::printf("false shadow on the lit ground at 4.8 deg (%s, filter %d): constant %.4f, adaptive %.4f\n",
                        cascades ? "csm" : "one map", int(filter), falseShadow[0], falseShadow[1]);
            EXPECT_LT(falseShadow[1], falseShadow[0]);
            EXPECT_LT(falseShadow[1], 0.005);
        }
}

TEST_F(Acne, EveryBiasCombinationRendersWithoutGlErrors) {
    for (DepthDistribution dist : {DepthDistribution::Hyperbolic, DepthDistribution::Linear})
        for (DepthOffset mode : {DepthOffset::None, DepthOffset::Constant, DepthOffset::SlopeScale, DepthOffset::Adaptive})
            for (bool back : {false, true})
                for (ShadowMethod m : {ShadowMethod::SsmFocused, ShadowMethod::Psm, ShadowMethod::Lispsm}) {
                    const Scene scene = planeBoxScene(fromSide());
                    Settings s = shadowView(m);
                    s.bias = {dist, mode, 0.002, 2.0, 4.0};
                    s.casters.singleSided = back ? CasterFaces::Back : CasterFaces::Front;
                    renderer_.reset();
                    const Classification k = classify(render(scene, s), s, fromSide(), 0.3);
                    // Every combination still shadows the box's shadow, and every one with an
                    // offset or back faces keeps the open ground lit (no acne, no self-shadowing
                    // of large polygons whose vertices lie outside the depth range).
                    const std::string what = std::string(methodName(m)) + " distribution " + std::to_string(int(dist)) +
                                             " offset " + std::to_string(int(mode)) + " back " + std::to_string(back);
                    EXPECT_LT(k.shadowButLit, k.shadow / 20 + 1) << what;
                    if (mode != DepthOffset::None || back) {
                        EXPECT_LT(k.litButDark, k.lit / 20 + 1) << what;
                    }
                }
}

// Eye-space blur (thesis 6.3): N = 4 changes only pixels near shadow boundaries of the N = 0 image,
// with one map and with cascades (the shadow term pass then looks up the split's layer).
class Blur : public RenderTest, public ::testing::WithParamInterface<bool> {};

TEST_P(Blur, ChangesOnlyPixelsNearShadowBoundaries) {
    const Scene scene = planeBoxScene(fromSide());
    Settings s = shadowView(ShadowMethod::Lispsm);
    s.filter.filter = ShadowFilter::Pcf2x2Hardware;
    s.csm.enabled = GetParam();
    s.csm.perSplit = SplitParameterization::Lispsm;
    const RgbaImage sharp = render(scene, s);
    s.filter.blurIterations = 4;
    FrameStats stats;
    const RgbaImage blurred = render(scene, s, &stats);
    const bool ranBlur = std::any_of(stats.passes.begin(), stats.passes.end(),
                                     [](const PassStats& p) { return p.name.rfind("blur", 0) == 0; });
    EXPECT_TRUE(ranBlur);
    const int w = sharp.width, h = sharp.height;
    // Boundary pixels of the sharp image: a dark and a bright pixel within their 3x3 neighbourhood.
    std::vector<std::uint8_t> boundary(std::size_t(w) * h, 0);
    for (int y = 1; y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            bool dark = false, bright = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const double l = luminance(sharp.at(x + dx, y + dy));
                    dark |= l < 150.0;
                    bright |= l > 220.0;
                }
            boundary[std::size_t(y) * w + x] = dark && bright;
        }
    // The blur's reach: 4 taps each side x strength 1 per pass, 4 iterations of x and y.
    const int reach = 4 * 4 + 2;
    int changed = 0, changedFar = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (std::abs(luminance(sharp.at(x, y)) - luminance(blurred.at(x, y))) <= 3.0) continue;
            ++changed;
            bool near = false;
            for (int dy = -reach; dy <= reach && !near; ++dy)
                for (int dx = -reach; dx <= reach && !near; ++dx) {
                    const int px = x + dx, py = y + dy;
                    near = px >= 0 && py >= 0 && px < w && py < h && boundary[std::size_t(py) * w + px];
                }
            changedFar += !near;
        }
    EXPECT_GT(changed, 50) << "the blur must soften the shadow outline";
    EXPECT_EQ(changedFar, 0) << "pixels far from any shadow boundary changed";
    // Away from the outline the blurred image keeps the ray cast's shadow and light.
    const Classification k = classify(blurred, s, fromSide(), 0.4);
    ASSERT_GT(k.shadow, 15);
    EXPECT_LT(k.shadowButLit, k.shadow * 2 / 100 + 1);
    EXPECT_LT(k.litButDark, k.lit * 2 / 100 + 1);
}

INSTANTIATE_TEST_SUITE_P(OneMapAndCascades, Blur, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& info) {
                             return std::string(info.param ? "csm" : "one_map");
                         });

TEST_F(Acne, BlurOffAllocatesNothingAndSameSettingsRenderIdentically) {
    const Scene scene = planeBoxScene(fromSide());
    Settings s = shadowView(ShadowMethod::Lispsm);
    FrameStats stats;
    const RgbaImage a = render(scene, s, &stats);
    for (const PassStats& p : stats.passes) EXPECT_TRUE(p.name.rfind("blur", 0) != 0 && p.name != "shadow term") << p.name;
    EXPECT_EQ(render(scene, s).pixels, a.pixels);
}

TEST_F(Acne, LitViewDarkensDiffuseInShadowButKeepsAmbient) {
    const glm::dvec3 light = fromSide();
    const Scene scene = planeBoxScene(light);
    Settings s = shadowView(ShadowMethod::Lispsm);
    s.viewMode = ViewMode::Lit;
    s.light.ambient = 0.2;
    const RgbaImage image = render(scene, s);
    double litSum = 0, shadowSum = 0;
    int lit = 0, shadow = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const Truth t = groundTruth(s, light, x, y, 0.3);
            if (t == Truth::Lit) litSum += luminance(image.at(x, y)), ++lit;
            if (t == Truth::Shadow) shadowSum += luminance(image.at(x, y)), ++shadow;
        }
    ASSERT_GT(lit, 0);
    ASSERT_GT(shadow, 0);
    const double litMean = litSum / lit, shadowMean = shadowSum / shadow;
    EXPECT_GT(litMean, shadowMean + 60.0);
    EXPECT_GT(shadowMean, 40.0) << "ambient is never shadowed";
}

}  // namespace
}  // namespace shadowlab::test
