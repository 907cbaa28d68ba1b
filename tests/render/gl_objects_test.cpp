// GL object owners and shader-file expansion: behaviour that needs no GL context.
#include "gl/gl_objects.h"
#include "shader_sources.h"

#include <gtest/gtest.h>

#include <type_traits>

namespace shadowlab {
namespace {

struct CountingTraits {
    static inline int destroyed = 0;
    static void destroy(GLuint) { ++destroyed; }
};
using Counted = gl::Object<CountingTraits>;

TEST(GlObject, DefaultHoldsNothingAndIsMoveOnly) {
    static_assert(!std::is_copy_constructible_v<gl::Buffer>);
    static_assert(!std::is_copy_assignable_v<gl::Texture>);
    static_assert(std::is_nothrow_move_constructible_v<gl::Framebuffer>);
    gl::Buffer none;  // constructible without a context
    EXPECT_FALSE(none);
    EXPECT_EQ(none.id(), 0u);
}

TEST(GlObject, MoveTransfersOwnershipAndDestroysOnce) {
    CountingTraits::destroyed = 0;
    {
        Counted a(7);
        Counted b(std::move(a));
        EXPECT_EQ(a.id(), 0u);
        EXPECT_EQ(b.id(), 7u);
        Counted c(9);
        c = std::move(b);  // 9 is destroyed, c takes 7
        EXPECT_EQ(CountingTraits::destroyed, 1);
        EXPECT_EQ(c.id(), 7u);
    }
    EXPECT_EQ(CountingTraits::destroyed, 2);
}

TEST(ShaderSources, IncludesAreExpandedOnceAndDefinesFollowVersion) {
    std::string error;
    const std::string text = shaders::expandedSource("forward.frag", "#define TEST_DEFINE 1\n", error);
    ASSERT_TRUE(error.empty()) << error;
    EXPECT_EQ(text.rfind("#version 450 core\n#define TEST_DEFINE 1\n", 0), 0u);
    EXPECT_EQ(text.find("#include"), std::string::npos);
    EXPECT_NE(text.find("float shadowTerm("), std::string::npos);
    // linear_depth.glsl is included by shadow_term.glsl; it must appear exactly once.
    const auto first = text.find("float linearDepth(");
    ASSERT_NE(first, std::string::npos);
    EXPECT_EQ(text.find("float linearDepth(", first + 1), std::string::npos);
}

TEST(ShaderSources, MissingFileIsAnErrorNamingIt) {
    std::string error;
    EXPECT_TRUE(shaders::expandedSource("no_such_shader.frag", "", error).empty());
    EXPECT_NE(error.find("no_such_shader.frag"), std::string::npos);
    EXPECT_FALSE(shaders::rawSource("no_such_shader.frag"));
}

}  // namespace
}  // namespace shadowlab
