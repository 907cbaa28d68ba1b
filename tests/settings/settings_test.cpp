// The settings contract: JSON round trip, --set keys, refusal of bad input, clamping.
#include "frame/frame_setup.h"
#include "settings/method_choice.h"
#include "settings/settings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace shadowlab {
namespace {

TEST(Settings, JsonRoundTripKeepsEveryValue) {
    Settings s;
    s.method = ShadowMethod::Psm;
    s.bias.mode = DepthOffset::Constant;
    s.bias.distribution = DepthDistribution::Linear;
    s.filter.blurIterations = 4;
    s.camera.position = {1.5, -2.0, 1e5};
    s.compare.count = 3;
    s.lispsm.virtualFar = 123.0;
    Settings back;
    std::string error;
    ASSERT_TRUE(fromJsonText(toJsonText(s), back, error)) << error;
    EXPECT_EQ(back, s);
}

TEST(Settings, PartialJsonChangesOnlyWhatItNames) {
    Settings s;
    std::string error;
    ASSERT_TRUE(fromJsonText(R"({"bias": {"slopeFactor": 3.5}, "method": "ssm"})", s, error)) << error;
    Settings expected;
    expected.bias.slopeFactor = 3.5;
    expected.method = ShadowMethod::SsmFocused;
    EXPECT_EQ(s, expected);
}

TEST(Settings, BadJsonIsRefusedAndLeavesSettingsUntouched) {
    Settings s;
    const Settings before = s;
    std::string error;
    EXPECT_FALSE(fromJsonText("{not json", s, error));
    EXPECT_FALSE(fromJsonText(R"({"bias": {"nope": 1}})", s, error));
    EXPECT_NE(error.find("bias.nope"), std::string::npos) << error;
    EXPECT_FALSE(fromJsonText(R"({"method": "csm"})", s, error));
    EXPECT_NE(error.find("method"), std::string::npos) << error;
    EXPECT_FALSE(fromJsonText(R"({"shadowMapSize": "big"})", s, error));
    EXPECT_FALSE(fromJsonText(R"({"shadowMapSize": 2.5})", s, error));
    EXPECT_EQ(s, before);
}

TEST(Settings, SetByKeyParsesByTheTypeFound) {
    Settings s;
    std::string error;
    ASSERT_TRUE(setByKey(s, "bias.mode=slope", error)) << error;
    EXPECT_EQ(s.bias.mode, DepthOffset::SlopeScale);
    ASSERT_TRUE(setByKey(s, "bias.mode=none", error)) << error;
    EXPECT_EQ(s.bias.mode, DepthOffset::None);
    ASSERT_TRUE(setByKey(s, "filter.blurIterations=8", error)) << error;
    EXPECT_EQ(s.filter.blurIterations, 8);
    ASSERT_TRUE(setByKey(s, "lispsm.useBodyVector=on", error)) << error;
    EXPECT_TRUE(s.lispsm.useBodyVector);
    ASSERT_TRUE(setByKey(s, "camera.position=1,2,3", error)) << error;
    EXPECT_EQ(s.camera.position, glm::dvec3(1, 2, 3));
    ASSERT_TRUE(setByKey(s, "compare.methods=psm,lispsm,ssm", error)) << error;
    EXPECT_EQ(s.compare.methods[0], (MethodChoice{ShadowMethod::Psm, false, {}}));
    EXPECT_FALSE(setByKey(s, "bias.mode=sloped", error));
    EXPECT_FALSE(setByKey(s, "bias=1", error));
    EXPECT_FALSE(setByKey(s, "nothing.here=1", error));
    EXPECT_FALSE(setByKey(s, "shadowMapSize=abc", error));
    EXPECT_FALSE(setByKey(s, "noequals", error));
}

TEST(Settings, SanitizeClampsAbsurdValuesAndReplacesNaN) {
    Settings s;
    s.shadowMapSize = 100000;
    s.camera.fovYDeg = std::numeric_limits<double>::quiet_NaN();
    s.camera.nearPlane = 0.0;
    s.camera.farPlane = -5.0;
    s.filter.blurIterations = 99;
    const auto changes = sanitize(s);
    EXPECT_GE(changes.size(), 5u);
    EXPECT_EQ(s.shadowMapSize, 8192);
    EXPECT_EQ(s.camera.fovYDeg, Settings().camera.fovYDeg);
    EXPECT_GT(s.camera.nearPlane, 0.0);
    EXPECT_GT(s.camera.farPlane, s.camera.nearPlane);
    EXPECT_EQ(s.filter.blurIterations, 16);
    Settings fine;
    EXPECT_TRUE(sanitize(fine).empty());
    s.shadowMapSize = 1000;
    sanitize(s);
    EXPECT_EQ(s.shadowMapSize, 1024);  // next power of two
}

TEST(FrameSetup, CameraFromSceneLooksWhereTheGltfCameraLooks) {
    Camera cam;
    // A camera at (0, 5, 10) rotated to look down the -Z axis tilted 30 degrees down.
    glm::dmat4 m(1.0);
    const double a = glm::radians(-30.0);
    m[1] = {0, std::cos(a), std::sin(a), 0};
    m[2] = {0, -std::sin(a), std::cos(a), 0};
    m[3] = {0, 5, 10, 1};
    cam.cameraToWorld = m;
    cam.yfov = float(glm::radians(45.0));
    cam.znear = 0.5f;
    cam.zfar = 200.0f;
    const CameraSettings s = cameraFromScene(cam, CameraSettings{});
    EXPECT_NEAR(s.pitchDeg, -30.0, 1e-6);
    const glm::dvec3 f = cameraForward(s);
    EXPECT_NEAR(f.z, -std::cos(glm::radians(30.0)), 1e-9);
    EXPECT_NEAR(s.fovYDeg, 45.0, 1e-4);
    EXPECT_EQ(s.position, glm::dvec3(0, 5, 10));
    EXPECT_FLOAT_EQ(float(s.farPlane), 200.0f);
}

TEST(FrameSetup, PointLightsAreLitButCastNoShadowWithANote) {
    Scene scene;
    Light lamp;
    lamp.type = LightType::Point;
    lamp.name = "Lamp";
    scene.lights.push_back(lamp);
    const LightFrame frame = resolveLight(scene, LightSettings{}, 0.0);
    EXPECT_FALSE(frame.castsShadow);
    EXPECT_NE(frame.note.find("Lamp"), std::string::npos);
}

TEST(FrameSetup, SunFromAzimuthElevationTravelsDownwards) {
    Scene scene;
    LightSettings l;
    l.source = LightSource::Sun;
    l.elevationDeg = 90.0;
    const LightFrame frame = resolveLight(scene, l, 0.0);
    EXPECT_NEAR(frame.direction.y, -1.0, 1e-12);
    l.elevationDeg = 30.0;
    l.animateSun = true;
    const LightFrame a = resolveLight(scene, l, 0.0), b = resolveLight(scene, l, 9.0);
    EXPECT_NEAR(a.direction.y, b.direction.y, 1e-12);  // the sun turns around the vertical
    EXPECT_GT(glm::length(a.direction - b.direction), 0.1);
}

TEST(FrameSetup, FrustumCullingKeepsVisibleAndStraddlingBoxesOnly) {
    CameraSettings cam;
    cam.position = {0, 0, 0};
    cam.yawDeg = -90.0;  // looking down -Z
    cam.pitchDeg = 0.0;
    cam.nearPlane = 0.1;
    cam.farPlane = 100.0;
    const ViewFrustum v = viewFrustum(cam, 1.0);
    const ClipPlanes planes = clipPlanes(v.projectionMatrix() * v.viewMatrix());
    auto box = [](glm::dvec3 c, double h) {
        Aabb b;
        b.extend(c - h);
        b.extend(c + h);
        return b;
    };
    EXPECT_TRUE(boxMayBeVisible(planes, box({0, 0, -10}, 1)));      // straight ahead
    EXPECT_FALSE(boxMayBeVisible(planes, box({0, 0, 10}, 1)));      // behind
    EXPECT_FALSE(boxMayBeVisible(planes, box({0, 0, -200}, 1)));    // beyond the far plane
    EXPECT_FALSE(boxMayBeVisible(planes, box({50, 0, -10}, 1)));    // far to the right
    EXPECT_TRUE(boxMayBeVisible(planes, box({0, 0, 0}, 5)));        // contains the eye
    EXPECT_TRUE(boxMayBeVisible(planes, box({0, 0, -100.5}, 1)));   // straddles the far plane
    EXPECT_FALSE(boxMayBeVisible(planes, Aabb{}));                  // empty
}

TEST(Settings, CascadeBlockRoundTripsAndSetsByKey) {
    Settings s;
    std::string error;
    ASSERT_TRUE(setByKey(s, "csm.enabled=true", error)) << error;
    ASSERT_TRUE(setByKey(s, "csm.perSplit=stable", error)) << error;
    ASSERT_TRUE(setByKey(s, "csm.splits=3", error)) << error;
    ASSERT_TRUE(setByKey(s, "csm.manualSplits=0.1,0.35", error)) << error;
    ASSERT_TRUE(setByKey(s, "bias.normalOffset=1.5", error)) << error;
    EXPECT_TRUE(s.csm.enabled);
    EXPECT_EQ(s.csm.perSplit, SplitParameterization::StableSsm);
    EXPECT_EQ(s.csm.manualSplits, (std::vector<double>{0.1, 0.35}));
    EXPECT_EQ(s.bias.normalOffset, 1.5);
    Settings back;
    ASSERT_TRUE(fromJsonText(toJsonText(s), back, error)) << error;
    EXPECT_EQ(back, s);
    EXPECT_FALSE(setByKey(s, "csm.perSplit=psm", error));
    EXPECT_NE(error.find("csm.perSplit"), std::string::npos) << error;
    bool listed = false;
    for (const auto& k : settingKeys(s)) listed |= k.rfind("csm.lambda=", 0) == 0;
    EXPECT_TRUE(listed);
}

// Split compare views are method names: cascades among them, and a view file from before
// cascades (one-map names only) loads as it was.
TEST(Settings, CompareMethodsAreNamesWithCascadesAndOldViewFilesStillLoad) {
    Settings s;
    std::string error;
    ASSERT_TRUE(setByKey(s, "compare.methods=ssm,csm-lispsm,csm-stable", error)) << error;
    const std::vector<MethodChoice> expected{{ShadowMethod::SsmFocused, false, {}},
                                             {ShadowMethod::Lispsm, true, SplitParameterization::Lispsm},
                                             {ShadowMethod::Lispsm, true, SplitParameterization::StableSsm}};
    EXPECT_EQ(s.compare.methods, expected);
    const std::string text = toJsonText(s);
    EXPECT_NE(text.find(R"("csm-lispsm")"), std::string::npos) << text;  // stored as the name
    Settings back;
    ASSERT_TRUE(fromJsonText(text, back, error)) << error;
    EXPECT_EQ(back.compare.methods, expected);
    // Every name round-trips, the plain "csm" (keeps csm.perSplit) too.
    for (const char* name : {"ssm", "ssm-unfocused", "psm", "lispsm", "csm", "csm-ssm", "csm-stable", "csm-lispsm"}) {
        ASSERT_TRUE(setByKey(s, std::string("compare.methods=psm,") + name, error)) << name << ": " << error;
        ASSERT_TRUE(fromJsonText(toJsonText(s), back, error)) << error;
        EXPECT_EQ(back.compare.methods, s.compare.methods) << name;
        EXPECT_EQ(methodChoiceName(back.compare.methods.at(1)), name);
    }
    // A view file of an earlier version (compare block with one-map names).
    Settings old;
    ASSERT_TRUE(fromJsonText(R"({"method": "lispsm", "compare": {"count": 3, "methods": ["ssm-unfocused", "psm", "lispsm"]}})",
                             old, error)) << error;
    EXPECT_EQ(old.compare.count, 3);
    EXPECT_EQ(old.compare.methods, (std::vector<MethodChoice>{{ShadowMethod::SsmUnfocused, false, {}},
                                                              {ShadowMethod::Psm, false, {}},
                                                              {ShadowMethod::Lispsm, false, {}}}));
    EXPECT_FALSE(fromJsonText(R"({"compare": {"methods": ["ssm", "csm-psm"]}})", old, error));
    EXPECT_NE(error.find("csm-lispsm"), std::string::npos) << error;  // the message lists the names
}

// The caster model's keys: faces by name, name lists (never numbers, even "1,2"), and the older
// bias.backFaces still loading: true is back-face rendering, false leaves the default.
TEST(Settings, CasterKeysAndOldBackFacesViewFilesLoad) {
    Settings s;
    std::string error;
    EXPECT_EQ(s.casters.singleSided, CasterFaces::Auto);
    ASSERT_TRUE(setByKey(s, "casters.singleSided=front", error)) << error;
    EXPECT_EQ(s.casters.singleSided, CasterFaces::Front);
    EXPECT_FALSE(setByKey(s, "casters.doubleSided=inside", error));
    EXPECT_NE(error.find("front, back, both, auto"), std::string::npos) << error;
    ASSERT_TRUE(setByKey(s, "casters.exclude=Sky*,1,2", error)) << error;
    EXPECT_EQ(s.casters.exclude, (std::vector<std::string>{"Sky*", "1", "2"}));
    ASSERT_TRUE(setByKey(s, "casters.include=7", error)) << error;
    EXPECT_EQ(s.casters.include, (std::vector<std::string>{"7"}));
    Settings back;
    ASSERT_TRUE(fromJsonText(toJsonText(s), back, error)) << error;
    EXPECT_EQ(back, s);
    EXPECT_FALSE(fromJsonText(R"({"casters": {"exclude": [1]}})", back, error));
    EXPECT_FALSE(fromJsonText(R"({"casters": {"exclude": ")" + std::string(300, 'x') + R"("}})", back, error));

    Settings old;
    ASSERT_TRUE(fromJsonText(R"({"bias": {"backFaces": true, "slopeFactor": 3.0}})", old, error)) << error;
    EXPECT_EQ(old.casters.singleSided, CasterFaces::Back);
    EXPECT_EQ(old.bias.slopeFactor, 3.0);
    ASSERT_TRUE(fromJsonText(R"({"bias": {"backFaces": false}})", old, error)) << error;
    EXPECT_EQ(old.casters.singleSided, CasterFaces::Auto);
    ASSERT_TRUE(setByKey(old, "bias.backFaces=on", error)) << error;
    EXPECT_EQ(old.casters.singleSided, CasterFaces::Back);
    EXPECT_FALSE(fromJsonText(R"({"bias": {"backFaces": "yes"}})", old, error));
    EXPECT_NE(error.find("bias.backFaces"), std::string::npos) << error;
    // A file naming both keeps the new key's choice.
    ASSERT_TRUE(fromJsonText(R"({"bias": {"backFaces": true}, "casters": {"singleSided": "both"}})", old, error));
    EXPECT_EQ(old.casters.singleSided, CasterFaces::Both);
    EXPECT_EQ(toJsonText(old).find("backFaces"), std::string::npos);  // written only as casters.*
}

TEST(Settings, SanitizeClampsCascadesAndDropsBadManualSplits) {
    Settings s;
    s.csm.splits = 9;
    s.csm.lambda = -2.0;
    s.csm.blendBand = std::nan("");
    s.csm.manualSplits = {0.5, 0.2, 0.9};  // 4 splits need 3 increasing values: these decrease
    const auto changes = sanitize(s);
    EXPECT_EQ(s.csm.splits, kMaxCascadeSplits);
    EXPECT_EQ(s.csm.lambda, 0.0);
    EXPECT_EQ(s.csm.blendBand, 0.0);
    EXPECT_TRUE(s.csm.manualSplits.empty());
    EXPECT_GE(changes.size(), 4u);
}

// bias.distribution=auto: linear depth exactly for the warped maps; explicit values win.
TEST(Settings, AutoDepthDistributionIsLinearForTheWarpsOnly) {
    Settings s;
    EXPECT_EQ(s.bias.distribution, DepthDistribution::Auto);
    for (auto [method, linear] : {std::pair{ShadowMethod::SsmFocused, false}, {ShadowMethod::SsmUnfocused, false},
                                  {ShadowMethod::Psm, true}, {ShadowMethod::Lispsm, true}}) {
        s.method = method;
        EXPECT_EQ(linearShadowDepth(s), linear) << methodName(method);
    }
    s.csm.enabled = true;  // the cascades' own parameterisation decides, not `method`
    for (auto [split, linear] : {std::pair{SplitParameterization::Ssm, false}, {SplitParameterization::StableSsm, false},
                                 {SplitParameterization::Lispsm, true}}) {
        s.csm.perSplit = split;
        EXPECT_EQ(linearShadowDepth(s), linear) << splitParameterizationName(split);
    }
    s.bias.distribution = DepthDistribution::Hyperbolic;
    EXPECT_FALSE(linearShadowDepth(s));
    s.bias.distribution = DepthDistribution::Linear;
    s.csm.enabled = false;
    s.method = ShadowMethod::SsmFocused;
    EXPECT_TRUE(linearShadowDepth(s));
}

}  // namespace
}  // namespace shadowlab
