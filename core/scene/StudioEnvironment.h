#pragma once
// The environment matevo ships, made by our own code so that image-based lighting works offline:
// a dim photo studio (dark floor, grey backdrop) with three soft boxes and a strip light. The
// key soft box sits in the direction of the paper's light (SceneSettings::lightDirection), so
// highlights fall where they do in the paper's scene. Linear radiance, lat-long (LatLong.h).
#include <filesystem>

#include "common/Image.h"
#include "common/Result.h"
#include "scene/PrefilteredEnvironment.h"

namespace matevo {

// The width of the lat-long studio image that loadEnvironment("studio") prefilters.
constexpr int kStudioSourceWidth = 512;

Image makeStudioEnvironment(int width = kStudioSourceWidth);

// "studio" for the generated one, prefiltered once and then read from the user's cache
// (scene/StudioEnvironmentCache.h), or a lat-long .hdr / .exr file (any image OpenImageIO
// reads), prefiltered. Errors name the file.
Result<PrefilteredEnvironment> loadEnvironment(const std::string& studioOrFile,
                                               const PrefilterSettings& settings = {});

}  // namespace matevo
