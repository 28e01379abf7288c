#pragma once

// Marks a per-pixel map over the shared colour formulas: flattened, its loop has no calls and no
// branches, so the compiler vectorises it, once per instruction set the CPU may have. Clang (the
// fuzz build) cannot combine flatten with target_clones, so there it is cloned only.
#if defined(__clang__)
#define MATEVO_VECTORISED_KERNEL [[gnu::target_clones("avx512f", "avx2", "default")]]
#else
#define MATEVO_VECTORISED_KERNEL [[gnu::flatten, gnu::target_clones("avx512f", "avx2", "default")]]
#endif
