#pragma once
// How closely the GPU renderer must match the CPU reference, in ΔE00 between the two renders of
// one material. Both shade from the same lobe tables, so they differ by float rounding only:
// measured on lavapipe over tests/gpu/GpuRenderTest's 350 images, at most MEAN_MEASURED mean and
// MAX_MEASURED at any one pixel. The bounds stand a few times above that, so that a real drift
// (a term shaded differently on one back end) fails long before anyone would see it.
namespace matevo::test {

// Per image, and for a figure pooled from one image (e.g. two back ends' mean ΔE00 to a target).
inline constexpr double kBackEndMeanDeltaE = 0.01;
// At any one pixel.
inline constexpr double kBackEndPixelDeltaE = 0.5;  // MEASURING

}  // namespace matevo::test
