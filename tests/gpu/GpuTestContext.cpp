#include "GpuTestContext.h"

#include <memory>
#include <string>

#include <gtest/gtest.h>

namespace matevo::test {

gpu::GpuContext* validatedContext() {
    static auto context = gpu::GpuContext::createHeadless({.validation = true});
    EXPECT_TRUE(context.ok()) << "no usable Vulkan device: " << context.error().message;
    return context.ok() ? &context.value() : nullptr;
}

void expectNoValidationMessages(const gpu::GpuContext& context) {
    const auto& log = context.instance.validationLog();
    std::string messages;
    for (const auto& message : log.messages()) messages += "\n  " + message;
    EXPECT_EQ(log.errorCount(), 0) << messages;
    EXPECT_EQ(log.warningCount(), 0) << messages;
}

void ValidatedGpuTest::SetUp() {
    context = validatedContext();
    ASSERT_NE(context, nullptr);
    auto created = gpu::CommandRunner::create(context->device);
    ASSERT_TRUE(created.ok()) << created.error().message;
    runner.emplace(std::move(created).value());
}

void ValidatedGpuTest::TearDown() {
    if (context) expectNoValidationMessages(*context);
}

}  // namespace matevo::test
