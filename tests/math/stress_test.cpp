// The stress suite (renderer/math/stress.h) with a smaller N than `shadowlab stress`, so CTest
// runs it on every build.
#include "math/stress.h"

#include <gtest/gtest.h>

namespace shadowlab {
namespace {

TEST(ShadowStress, RandomConfigurationsHaveNoNanAndContainB) {
    StressOptions options;
    options.cases = 20000;
    options.seed = 20261122;
    const StressReport report = runStress(options);
    SCOPED_TRACE(report.text());
    std::cout << report.text();
    EXPECT_EQ(report.cases, options.cases);
    EXPECT_EQ(report.samplesOutsideB, 0u);
    EXPECT_EQ(report.directionalEmptyB, 0u);
    ASSERT_EQ(report.methods.size(), 4u);
    for (const auto& m : report.methods) {
        EXPECT_EQ(m.cases, options.cases) << shadowMethodName(m.method);
        EXPECT_EQ(m.nanInf, 0u) << shadowMethodName(m.method);
        EXPECT_EQ(m.containmentFailures, 0u) << shadowMethodName(m.method);
        // Most random cases see something lit: the suite must exercise the methods, not skip them.
        EXPECT_GT(m.valid, options.cases / 4) << shadowMethodName(m.method);
    }
    EXPECT_TRUE(report.passed());
}

// A spot light ~7e4 from the origin: if its near cap plane is matched with the light axis
// instead of its own normal, the cap survives in culling and a caster between the
// apex and L's near plane is culled (seed 1, case 122134 of 200,000).
TEST(ShadowStress, SpotCapFarFromTheOriginKeepsCastersNearTheApex) {
    StressOptions options;
    options.seed = 1;
    options.firstCase = 122134;
    options.cases = 1;
    options.samplesPerCase = 8;
    const StressReport report = runStress(options);
    EXPECT_EQ(report.cullingFailures, 0u) << report.text();
    EXPECT_TRUE(report.passed()) << report.text();
}

TEST(ShadowStress, SameSeedSameReport) {
    StressOptions options;
    options.cases = 200;
    options.seed = 7;
    const StressReport a = runStress(options), b = runStress(options);
    ASSERT_EQ(a.methods.size(), b.methods.size());
    EXPECT_EQ(a.emptyB, b.emptyB);
    for (std::size_t i = 0; i < a.methods.size(); ++i) {
        EXPECT_EQ(a.methods[i].valid, b.methods[i].valid);
        EXPECT_EQ(a.methods[i].fallbacks, b.methods[i].fallbacks);
        EXPECT_EQ(a.methods[i].worstExcess, b.methods[i].worstExcess);
    }
}

}  // namespace
}  // namespace shadowlab
