#pragma once
// `--backend gpu|cpu` and `--no-fallback`, which the rendering commands take; what they select is
// made by gpu::createPopulationRenderer.
#include <filesystem>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "gpu/PopulationRendererFactory.h"
#include "render/PopulationRenderer.h"

namespace matevo::cli {

class CommandLine;

// Throws UsageError naming the option for a name not in kRenderBackends.
RenderBackend parseRenderBackend(const std::string& text, const std::string& option);

// --backend (default gpu) and --no-fallback (only with the GPU, which it makes strict) of a
// command, as a request to fill in further; `who` prefixes the fallback notice.
gpu::RendererRequest backendOptions(CommandLine& args, const std::string& who);

// The renderer `request` asks for; a GPU that --no-fallback requires and that is not usable is
// a CommandFailure of kind Environment (exit 1).
std::unique_ptr<PopulationRenderer> createCommandRenderer(const gpu::RendererRequest& request,
                                                          const SceneTextures& textures);
// The same for a preset, its textures loaded (gpu::createPresetRenderer); a texture that cannot
// be read is a UsageError naming the preset file and field.
std::unique_ptr<PopulationRenderer> createCommandRenderer(const gpu::RendererRequest& request,
                                                          const Preset& preset,
                                                          const std::filesystem::path& presetFile);

// What made a report's renders, so that work of different back ends or versions is never
// joined (merge, a resumed share): {"matevo": version, "backend": "gpu"|"cpu", "device": name}.
nlohmann::ordered_json madeBy(const PopulationRenderer& renderer);

}  // namespace matevo::cli
