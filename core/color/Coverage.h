#pragma once
// Which pixels an image covers: the one rule of every image difference (compareImages,
// LabImage, FLIP and the GPU passes in shaders/DeltaE00.comp and FlipCombine.comp). A
// pixel counts when its alpha is at least 0.5, so a half-covered silhouette pixel counts. The
// rule survives 8-bit storage: a PNG stores round(255 alpha), which is 128 or more exactly when
// alpha >= 0.5, so a difference measured on renders and one measured on the PNG files written
// from them pool the same pixels.
namespace matevo {

constexpr float kCoverageThreshold = 0.5f;

constexpr bool isCovered(float alpha) { return alpha >= kCoverageThreshold; }

}  // namespace matevo
