#pragma once
// The environment seen behind a rendered scene: what a camera would see where no instance
// covers the pixel, slightly blurred (a roughness level of the prefiltered environment, as a
// photographer's shallow depth of field would soften a studio). Premultiplied "over": the
// result is opaque.
#include "common/Image.h"
#include "scene/PrefilteredEnvironment.h"
#include "scene/SceneLayout.h"

namespace matevo {

constexpr double kBackdropBlurAlpha = 0.03;

void compositeOverEnvironment(Image& image, const SceneCamera& camera,
                              const PrefilteredEnvironment& environment,
                              double blurAlpha = kBackdropBlurAlpha);

}  // namespace matevo
