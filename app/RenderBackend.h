#pragma once
// Headless rendering for the commands: on the GPU when a Vulkan device is usable, otherwise on
// the CPU reference renderer with a one-line notice on stderr (the same pictures either way,
// to within the cross-check of tests/gpu).
#include <span>
#include <string>
#include <vector>

#include "common/Image.h"
#include "material/MaterialInstance.h"
#include "scene/SceneSettings.h"
#include "scene/SceneTextures.h"

namespace matevo::cli {

enum class RenderBackend { Gpu, Cpu };

// Throws UsageError naming the option for anything but "gpu" or "cpu".
RenderBackend parseRenderBackend(const std::string& text, const std::string& option);

// The one-line notice printed when the GPU is not usable and the CPU takes over.
void noticeCpuFallback(const std::string& command, const std::string& reason);

// `command` prefixes the fallback notice, e.g. "matevo render".
std::vector<Image> renderMaterials(std::span<const MaterialInstance> materials,
                                   const SceneTextures& textures, const SceneSettings& scene,
                                   int size, RenderBackend backend, const std::string& command);

}  // namespace matevo::cli
