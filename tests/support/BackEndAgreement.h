#pragma once
// How closely the GPU renderer must match the CPU reference, in ΔE00 between the two renders of
// one material. Both shade from the same lobe tables, so they differ by float rounding only:
// measured on lavapipe over tests/gpu/GpuRenderTest's 358 images, at most 0.00003 mean and 0.019
// at any one pixel. The bounds stand well above that (the pixel one about five times), yet a
// real drift (a term shaded differently on one back end) fails them long before anyone would
// see it.
namespace matevo::test {

// Per image, and for a figure pooled from one image (e.g. two back ends' mean ΔE00 to a target).
inline constexpr double kBackEndMeanDeltaE = 0.01;
// At any one pixel.
inline constexpr double kBackEndPixelDeltaE = 0.1;

}  // namespace matevo::test
