#pragma once
// The attribute of a hot loop over float math: flattened, the loop has no calls, and it is
// compiled for AVX-512, AVX2 and the baseline, chosen at run time, so the compiler vectorises it
// as wide as the machine allows. Clang (the fuzz build) cannot combine flatten with
// target_clones.
#if defined(__clang__)
#define MATEVO_VECTORISED_KERNEL [[gnu::target_clones("avx512f", "avx2", "default")]]
#else
#define MATEVO_VECTORISED_KERNEL [[gnu::flatten, gnu::target_clones("avx512f", "avx2", "default")]]
#endif
