// The bench spec's "methods", "csmLayers" and "csmPlacements" (app/commands/bench_spec.h) and the method names they use
// (settings/method_choice.h): cascaded choices parse, bad names fail with the list of good ones,
// and equal memory gives 4 splits layers of half the map's side.
#include "commands/bench_spec.h"

#include <gtest/gtest.h>

namespace shadowlab::app {
namespace {

const char* kScenes = R"("scenes": [ { "file": "a.glb" } ])";

bool parse(const std::string& body, BenchSpec& spec, std::string& error) {
    return parseBenchSpec("{ " + std::string(kScenes) + (body.empty() ? "" : ", " + body) + " }", "", spec, error);
}

TEST(MethodChoice, EveryNameRoundTrips) {
    for (const char* name : {"ssm", "ssm-unfocused", "psm", "lispsm", "csm", "csm-ssm", "csm-stable", "csm-lispsm"}) {
        MethodChoice c;
        ASSERT_TRUE(parseMethodChoice(name, c)) << name;
        EXPECT_EQ(methodChoiceName(c), name);
    }
    MethodChoice c;
    for (const char* bad : {"", "csm-", "csm-psm", "CSM", "lispsm ", "csmlispsm", "all"})
        EXPECT_FALSE(parseMethodChoice(bad, c)) << bad;
}

TEST(MethodChoice, ApplyingSetsCsmOrTheMethod) {
    Settings s;
    MethodChoice c;
    ASSERT_TRUE(parseMethodChoice("csm-stable", c));
    applyMethodChoice(s, c);
    EXPECT_TRUE(s.csm.enabled);
    EXPECT_EQ(s.csm.perSplit, SplitParameterization::StableSsm);
    EXPECT_EQ(methodChoiceName(methodChoiceOf(s)), "csm-stable");
    s.csm.perSplit = SplitParameterization::Lispsm;
    ASSERT_TRUE(parseMethodChoice("csm", c));  // keeps csm.perSplit
    applyMethodChoice(s, c);
    EXPECT_EQ(s.csm.perSplit, SplitParameterization::Lispsm);
    ASSERT_TRUE(parseMethodChoice("psm", c));
    applyMethodChoice(s, c);
    EXPECT_FALSE(s.csm.enabled);
    EXPECT_EQ(s.method, ShadowMethod::Psm);
    EXPECT_EQ(allMethodChoices().size(), 6u);
}

TEST(MethodChoice, EqualMemoryLayers) {
    EXPECT_EQ(equalMemoryLayerSize(2048, 4), 1024);
    EXPECT_EQ(equalMemoryLayerSize(2048, 1), 2048);
    EXPECT_EQ(equalMemoryLayerSize(2048, 2), 1024);  // powers of two: half the memory
    EXPECT_EQ(equalMemoryLayerSize(2048, 3), 1024);
    EXPECT_EQ(equalMemoryLayerSize(256, 4), 256);  // never below the smallest map
    Settings s;
    s.shadowMapSize = 1024;
    s.csm.enabled = true;
    s.csm.splits = 4;
    EXPECT_EQ(shadowMapTexels(s), 4LL * 1024 * 1024);
}

TEST(BenchSpecMethods, CascadedNamesParseInOrderWithoutDuplicates) {
    BenchSpec spec;
    std::string error;
    ASSERT_TRUE(parse(R"("methods": ["ssm", "csm-lispsm", "csm-stable", "csm-lispsm", "csm"])", spec, error)) << error;
    ASSERT_EQ(spec.methods.size(), 4u);
    EXPECT_EQ(methodChoiceName(spec.methods[1]), "csm-lispsm");
    EXPECT_EQ(methodChoiceName(spec.methods[3]), "csm");
    EXPECT_TRUE(spec.csmEqualMemory);  // the default
    EXPECT_EQ(spec.caseCount(), 4u);
}

TEST(BenchSpecMethods, BadNamesAndLayerModesFailWithTheKey) {
    BenchSpec spec;
    std::string error;
    EXPECT_FALSE(parse(R"("methods": ["csm-psm"])", spec, error));
    EXPECT_NE(error.find("\"methods\""), std::string::npos) << error;
    EXPECT_NE(error.find("csm-stable"), std::string::npos) << "the message lists the names: " << error;
    EXPECT_FALSE(parse(R"("methods": [3])", spec, error));
    EXPECT_FALSE(parse(R"("csmLayers": "half")", spec, error));
    EXPECT_NE(error.find("\"csmLayers\""), std::string::npos) << error;
    ASSERT_TRUE(parse(R"("csmLayers": "mapSize")", spec, error)) << error;
    EXPECT_FALSE(spec.csmEqualMemory);
}

TEST(BenchSpecMethods, CsmPlacementsRunEachCascadeOncePerPlacement) {
    BenchSpec spec;
    std::string error;
    ASSERT_TRUE(parse(R"("methods": ["lispsm", "csm-lispsm", "csm-ssm"], "csmPlacements": ["lambda", "sdsm", "sdsm"])",
                      spec, error))
        << error;
    ASSERT_EQ(spec.csmPlacements.size(), 2u);  // duplicates dropped
    EXPECT_EQ(spec.placementsFor(spec.methods[0]).size(), 1u);  // one map: once, placement unset
    EXPECT_FALSE(spec.placementsFor(spec.methods[0])[0].has_value());
    ASSERT_EQ(spec.placementsFor(spec.methods[1]).size(), 2u);
    EXPECT_EQ(*spec.placementsFor(spec.methods[1])[1], SplitPlacement::Sdsm);
    EXPECT_EQ(spec.caseCount(), 5u);
    EXPECT_FALSE(parse(R"("csmPlacements": ["log"])", spec, error));
    EXPECT_NE(error.find("\"csmPlacements\""), std::string::npos) << error;
    ASSERT_TRUE(parse(R"("methods": ["csm-lispsm"])", spec, error)) << error;
    EXPECT_EQ(spec.caseCount(), 1u);  // without the key: the variant's placement
}

TEST(BenchSpecMethods, ACaseAtEqualMemoryHasTheTexelsOfTheOneMap) {
    MethodChoice csm, ssm;
    ASSERT_TRUE(parseMethodChoice("csm-lispsm", csm));
    ASSERT_TRUE(parseMethodChoice("ssm", ssm));
    Settings a, b, c;
    applyBenchCase(a, csm, 2048, true);
    applyBenchCase(b, ssm, 2048, true);
    applyBenchCase(c, csm, 2048, false);
    EXPECT_EQ(a.shadowMapSize, 1024);
    EXPECT_EQ(shadowMapTexels(a), shadowMapTexels(b));
    EXPECT_EQ(c.shadowMapSize, 2048);
    EXPECT_EQ(shadowMapTexels(c), 4 * shadowMapTexels(b));
    Settings two;
    two.csm.splits = 2;
    applyBenchCase(two, csm, 2048, true);
    EXPECT_LE(shadowMapTexels(two), shadowMapTexels(b));  // never more memory than the one map
}

}  // namespace
}  // namespace shadowlab::app
