#pragma once
// Our own textures for the validation presets (we have no copies of the paper's): periodic
// value-noise patterns on the sphere's equirectangular (u, v) domain (SphereMapping.h), 2:1.
// Deterministic: a fixed integer hash, no random engine.
#include "common/Image.h"

namespace matevo {

// Painted metal's top-layer roughness: a fairly smooth paint (texel ~0.1, so alpha1 = 2.5 gives
// ~0.25) with rough worn patches (texel up to ~0.36) and fine grain. Grey, linear values.
Image makePaintRoughnessTexture(int width, int height);

// Metal depth's base colour: warm metal tones in turbulent bands. Linear RGB.
Image makeMetalDepthBaseColorTexture(int width, int height);

}  // namespace matevo
