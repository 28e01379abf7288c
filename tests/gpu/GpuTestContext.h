#pragma once
// One validated Vulkan context per test process (lavapipe JIT-compiles each pipeline on first
// use, so passes are created once and reused), and the check that fails a test on any
// validation error or warning.
#include "gpu/DeltaE00Pass.h"
#include "gpu/GpuContext.h"

namespace matevo::test {

// Fails the current test (and returns nullptr) when no Vulkan device is found: GPU tests are
// never skipped.
gpu::GpuContext* validatedContext();

// Adds a test failure listing the messages if the messenger heard any error or warning.
void expectNoValidationMessages(const gpu::GpuContext& context);

// A colormap whose red channel is the entry's position, so tests can read ΔE00 back from it.
gpu::DeltaE00Pass::Colormap rampColormap();

}  // namespace matevo::test
