// Hostile settings input: --set values and view JSON that could reach
// undefined float->int casts, leak library messages, echo 50 MB values or be accepted silently.
// Every case is refused with a message naming the key, or clamped by sanitize with a notice.
#include "settings/settings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace shadowlab {
namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(SettingsInput, HugeNumbersForIntegersAreRefusedBeforeAnyConversion) {
    Settings s;
    const Settings before = s;
    std::string error;
    EXPECT_FALSE(setByKey(s, "shadowMapSize=1e10", error));
    EXPECT_TRUE(contains(error, "'shadowMapSize' expects a whole number in 256 .. 8192")) << error;
    EXPECT_FALSE(fromJsonText(R"({"shadowMapSize": 1e300})", s, error));
    EXPECT_TRUE(contains(error, "shadowMapSize")) << error;
    EXPECT_FALSE(fromJsonText(R"({"filter": {"blurIterations": -3e9}})", s, error));
    EXPECT_FALSE(fromJsonText(R"({"compare": {"count": 18446744073709551615}})", s, error));
    EXPECT_TRUE(contains(error, "compare.count")) << error;
    EXPECT_EQ(s, before);
}

TEST(SettingsInput, AbsurdButRepresentableValuesAreClampedWithANotice) {
    Settings s;
    std::string error;
    for (const char* set : {"shadowMapSize=1000000", "filter.blurIterations=100000", "camera.nearPlane=0",
                            "camera.farPlane=-1", "light.spotOuterConeDeg=180", "light.elevationDeg=400"})
        ASSERT_TRUE(setByKey(s, set, error)) << set << ": " << error;
    const std::vector<std::string> notices = sanitize(s);
    EXPECT_EQ(s.shadowMapSize, 8192);
    EXPECT_EQ(s.filter.blurIterations, 16);
    EXPECT_GT(s.camera.nearPlane, 0.0);
    EXPECT_GT(s.camera.farPlane, s.camera.nearPlane);
    EXPECT_EQ(s.light.spotOuterConeDeg, 89.0);
    EXPECT_EQ(s.light.elevationDeg, 90.0);
    for (const char* key : {"shadowMapSize", "filter.blurIterations", "camera.nearPlane", "camera.farPlane",
                            "light.spotOuterConeDeg", "light.elevationDeg"})
        EXPECT_TRUE(std::any_of(notices.begin(), notices.end(), [&](const std::string& n) { return contains(n, key); }))
            << key;
    ASSERT_TRUE(setByKey(s, "light.spotOuterConeDeg=0", error));
    sanitize(s);
    EXPECT_EQ(s.light.spotOuterConeDeg, 1.0);
}

TEST(SettingsInput, NonFiniteAndMalformedVectorsNameTheKeyInPlainWords) {
    Settings s;
    std::string error;
    for (const char* bad : {"camera.position=nan,0,0", "camera.position=inf,0,0", "camera.position=1,2",
                            "camera.position=a,b,c", "light.color=1,2,3,4"}) {
        EXPECT_FALSE(setByKey(s, bad, error)) << bad;
        EXPECT_TRUE(contains(error, "expects 3 finite numbers [x, y, z]")) << error;
        EXPECT_FALSE(contains(error, "json.exception")) << error;
    }
    EXPECT_FALSE(fromJsonText(R"({"camera": {"position": [1, "2", 3]}})", s, error));
    EXPECT_TRUE(contains(error, "camera.position")) << error;
    EXPECT_FALSE(fromJsonText(R"({"camera": {"position": 5}})", s, error));
    EXPECT_FALSE(contains(error, "a array")) << error;
    EXPECT_FALSE(fromJsonText(R"({"light": {"animateSun": "yes"}})", s, error));
    EXPECT_TRUE(contains(error, "'light.animateSun' expects true or false")) << error;
}

TEST(SettingsInput, ChoicesAreListedWhenAValueIsNotOne) {
    Settings s;
    std::string error;
    EXPECT_FALSE(setByKey(s, "bias.mode=sloped", error));
    EXPECT_TRUE(contains(error, "expects one of none, constant, slope, adaptive, got 'sloped'")) << error;
    EXPECT_FALSE(fromJsonText(R"({"method": "csm"})", s, error));
    EXPECT_TRUE(contains(error, "ssm, ssm-unfocused, psm, lispsm")) << error;
    EXPECT_FALSE(setByKey(s, "compare.methods=ssm,csm-psm", error));  // PSM per split is not offered
    EXPECT_TRUE(contains(error, "'csm-psm'")) << error;
    EXPECT_TRUE(contains(error, "csm-stable, csm-lispsm")) << error;
    EXPECT_FALSE(setByKey(s, "nothing=1", error));
    EXPECT_TRUE(contains(error, "see `shadowlab settings`")) << error;
}

TEST(SettingsInput, LongValuesAreCutInMessages) {
    Settings s;
    std::string error;
    const std::string huge(1 << 20, 'x');
    EXPECT_FALSE(setByKey(s, "bias.mode=" + huge, error));
    EXPECT_LT(error.size(), 300u);
    EXPECT_FALSE(setByKey(s, huge + "=1", error));
    EXPECT_LT(error.size(), 300u);
    EXPECT_FALSE(fromJsonText("{\"method\": \"" + huge + "\"}", s, error));
    EXPECT_LT(error.size(), 300u);
}

TEST(SettingsInput, JsonErrorsGiveLineAndColumnAndHugeTextsAreRefusedUnparsed) {
    Settings s;
    std::string error;
    EXPECT_FALSE(fromJsonText("{\n  \"method\": \"psm\",\n  \"shadows\": tru\n}", s, error));
    EXPECT_TRUE(contains(error, "not valid JSON at line 3, column")) << error;
    std::string methods = R"({"compare": {"methods": [)";
    for (int i = 0; i < 200000; ++i) methods += "\"ssm\",";
    methods += "\"ssm\"]}}";
    EXPECT_FALSE(fromJsonText(methods, s, error));
    EXPECT_TRUE(contains(error, "at most 1048576 bytes")) << error;
}

TEST(SettingsInput, MethodListsAreTruncatedToTheThreeViewsUsed) {
    Settings s;
    std::string error;
    ASSERT_TRUE(setByKey(s, "compare.methods=psm,psm,lispsm,ssm,ssm", error)) << error;
    const std::vector<std::string> notices = sanitize(s);
    EXPECT_EQ(s.compare.methods, (std::vector<MethodChoice>{{ShadowMethod::Psm, false, {}},
                                                            {ShadowMethod::Psm, false, {}},
                                                            {ShadowMethod::Lispsm, false, {}}}));
    EXPECT_EQ(notices.size(), 1u);
    EXPECT_TRUE(contains(notices.at(0), "5 entries, the first 3 are used"));
    // A short list is filled from the defaults (ssm, psm, lispsm) after its own entries.
    ASSERT_TRUE(setByKey(s, "compare.methods=csm-lispsm", error)) << error;
    EXPECT_EQ(sanitize(s).size(), 1u);
    EXPECT_EQ(s.compare.methods, (std::vector<MethodChoice>{{ShadowMethod::Lispsm, true, SplitParameterization::Lispsm},
                                                            {ShadowMethod::Psm, false, {}},
                                                            {ShadowMethod::Lispsm, false, {}}}));
}

// `shadowlab settings` offers the cascade names for the compare views.
TEST(SettingsInput, TheCompareListOffersEveryMethodName) {
    for (const SettingDescription& d : describeSettings())
        if (d.key == "compare.methods") {
            EXPECT_EQ(d.type, "list");
            EXPECT_TRUE(contains(d.range, "csm-ssm, csm-stable, csm-lispsm")) << d.range;
            EXPECT_EQ(d.defaultValue, "ssm,psm,lispsm");
            return;
        }
    ADD_FAILURE() << "compare.methods is not listed";
}

// The listing `shadowlab settings` prints covers every key, with a range for every number that is
// the range sanitize() clamps to, and defaults inside it.
TEST(SettingsInput, TheListingDescribesEveryKeyWithTheRangeSanitizeUses) {
    const std::vector<SettingDescription> described = describeSettings();
    std::set<std::string> keys;
    for (const SettingDescription& d : described) {
        keys.insert(d.key);
        EXPECT_FALSE(d.type.empty()) << d.key;
        EXPECT_FALSE(d.range.empty()) << d.key;
        EXPECT_FALSE(d.defaultValue.empty()) << d.key;
        if (d.type == "choice" || d.type == "list") {
            EXPECT_FALSE(settingChoices(d.key).empty()) << d.key;
        }
    }
    for (const std::string& keyValue : settingKeys(Settings{}))
        EXPECT_TRUE(keys.count(keyValue.substr(0, keyValue.find('=')))) << keyValue;

    // Every ranged number: one below the range clamps to lo, one above to hi.
    for (const SettingDescription& d : described) {
        double lo = 0, hi = 0;
        if (!settingRange(d.key, lo, hi) || d.type == "x,y,z") continue;
        for (const double outside : {lo - 1.0 - std::abs(lo), hi + 1.0 + std::abs(hi)}) {
            Settings s;
            std::string error;
            const std::string value = d.type == "integer" ? std::to_string(std::llround(outside)) : std::to_string(outside);
            if (!setByKey(s, d.key + "=" + value, error)) continue;  // beyond int: refused, tested above
            sanitize(s);
            const std::string after = [&] {
                for (const std::string& kv : settingKeys(s))
                    if (kv.rfind(d.key + "=", 0) == 0) return kv.substr(d.key.size() + 1);
                return std::string();
            }();
            const double v = std::stod(after);
            EXPECT_GE(v, lo) << d.key;
            EXPECT_LE(v, hi) << d.key;
        }
    }
}

TEST(SettingsInput, SettingsTheSceneMakesMeaninglessGiveNotices) {
    Settings s;
    EXPECT_TRUE(sceneNotices(s, 1).empty());
    s.light.sceneLight = 5;
    ASSERT_EQ(sceneNotices(s, 1).size(), 1u);
    EXPECT_TRUE(contains(sceneNotices(s, 1)[0], "light.sceneLight = 5, but the scene has 1 light"));
    s.light.sceneLight = 0;
    s.light.animateSun = true;
    ASSERT_EQ(sceneNotices(s, 1).size(), 1u);
    EXPECT_TRUE(contains(sceneNotices(s, 1)[0], "light.animateSun has no effect"));
    s.light.source = LightSource::Sun;
    EXPECT_TRUE(sceneNotices(s, 1).empty());
}

}  // namespace
}  // namespace shadowlab

namespace shadowlab {
namespace {

// Found by fuzz_settings: without a guard both abort the process with an uncaught json exception.
TEST(SettingsInput, FuzzFoundInputsGiveMessagesNotAborts) {
    Settings s;
    std::string error;
    EXPECT_FALSE(setByKey(s, "camera.position=\xff", error));  // invalid UTF-8 in a list value
    EXPECT_NE(error.find("camera.position"), std::string::npos) << error;
    error.clear();
    EXPECT_FALSE(fromJsonText("{\"shadowMapSize\": 2e2002}", s, error));  // beyond any double
    EXPECT_NE(error.find("out of the range"), std::string::npos) << error;
    EXPECT_EQ(error.find("json.exception"), std::string::npos) << error;
}

}  // namespace
}  // namespace shadowlab
