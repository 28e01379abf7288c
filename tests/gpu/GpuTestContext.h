#pragma once
// One validated Vulkan context per test process (lavapipe JIT-compiles each pipeline on first
// use, so passes are created once and reused), and the check that fails a test on any
// validation error or warning.
#include <optional>

#include <gtest/gtest.h>

#include "gpu/CommandRunner.h"
#include "gpu/GpuContext.h"

namespace matevo::test {

// Fails the current test (and returns nullptr) when no Vulkan device is found: GPU tests are
// never skipped.
gpu::GpuContext* validatedContext();

// Adds a test failure listing the messages if the messenger heard any error or warning.
void expectNoValidationMessages(const gpu::GpuContext& context);

// A test on the process's validated context with a command runner of its own, failed by any
// validation message heard by its end.
class ValidatedGpuTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;

    gpu::GpuContext* context = nullptr;
    std::optional<gpu::CommandRunner> runner;
};

}  // namespace matevo::test
