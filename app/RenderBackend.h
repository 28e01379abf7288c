#pragma once
// `--backend gpu|cpu`, which every rendering command and the editor take; what it selects is
// made by gpu::createPopulationRenderer.
#include <string>

#include "render/PopulationRenderer.h"

namespace matevo::cli {

// Throws UsageError naming the option for anything but "gpu" or "cpu".
RenderBackend parseRenderBackend(const std::string& text, const std::string& option);

}  // namespace matevo::cli
