#pragma once
// Tests that use a Vulkan device: the validation layer is always on and any
// message it reports fails the test.
#include "engine/vk/context.h"

#include <gtest/gtest.h>

#include <memory>

namespace grotto::test {

class GpuTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { ctx_ = std::make_unique<vk::Context>(vk::ContextOptions{.validation = true}); }
    static void TearDownTestSuite() { ctx_.reset(); }
    void TearDown() override { EXPECT_EQ(ctx_->validationMessages(), 0) << "validation layer reported messages"; }
    vk::Context& ctx() { return *ctx_; }

private:
    static inline std::unique_ptr<vk::Context> ctx_;
};

}  // namespace grotto::test
