#pragma once
// One headless EGL context per test process, with the KHR_debug error counter installed.
#include "gl/debug_output.h"
#include "gl/headless_context.h"

#include <gtest/gtest.h>

#include <memory>

namespace shadowlab::test {

class GlTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        std::string error;
        context() = HeadlessContext::create(error);
        ASSERT_TRUE(context()) << error;
        gl::installDebugOutput(debugLog());
    }
    static void TearDownTestSuite() { context().reset(); }
    void SetUp() override { debugLog().errorCount = 0; }
    void TearDown() override {
        EXPECT_EQ(debugLog().errorCount, 0u) << "GL errors: " << (debugLog().messages.empty() ? "" : debugLog().messages.back());
    }
    static std::unique_ptr<HeadlessContext>& context() {
        static std::unique_ptr<HeadlessContext> c;
        return c;
    }
    static gl::DebugLog& debugLog() {
        static gl::DebugLog log;
        return log;
    }
};

}  // namespace shadowlab::test
