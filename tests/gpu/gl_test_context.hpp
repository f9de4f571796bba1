// A headless GL 4.5 context for GPU tests (llvmpipe where there is no GPU), created once per
// test program, with debug output on: a test fails if the GL reported any error.
#pragma once

#include "common/context.hpp"
#include "common/gl_debug.hpp"

#include <gtest/gtest.h>

#include <memory>

namespace ocean_test {

class GlEnvironment : public ::testing::Environment {
public:
    void SetUp() override {
        context_ = ocean::Context::create({true, 64, 64, "gpu tests"});
        ocean::enable_gl_debug_output();
        // A surfaceless context has no default framebuffer: draws go to the offscreen target.
        glBindFramebuffer(GL_FRAMEBUFFER, context_->target_framebuffer());
        std::printf("GL: %s\n", context_->description().c_str());
    }
    void TearDown() override { context_.reset(); }

private:
    std::unique_ptr<ocean::Context> context_;
};

// Checks at the end of each test that the GL reported no error during it.
class GlTest : public ::testing::Test {
protected:
    void SetUp() override { errors_before_ = ocean::gl_debug_stats().errors; }
    void TearDown() override {
        ocean::check_gl_errors("the test");
        EXPECT_EQ(ocean::gl_debug_stats().errors, errors_before_)
            << "GL error: " << ocean::gl_debug_stats().first_error;
    }

private:
    int errors_before_ = 0;
};

}  // namespace ocean_test
