#include "RenderBackend.h"

#include "CommandLine.h"

namespace matevo::cli {

RenderBackend parseRenderBackend(const std::string& text, const std::string& option) {
    return parseChoiceOption(kRenderBackends, text, option, "back end");
}

gpu::RendererRequest backendOptions(CommandLine& args, const std::string& who) {
    gpu::RendererRequest request(
        parseRenderBackend(args.option("--backend").value_or("gpu"), "--backend"), who);
    request.noFallback = args.flag("--no-fallback");
    if (request.noFallback && request.backend == RenderBackend::Cpu)
        throw UsageError(
            "--no-fallback: forbids falling back from the GPU; --backend cpu has "
            "nothing to fall back from");
    return request;
}

std::unique_ptr<PopulationRenderer> createCommandRenderer(const gpu::RendererRequest& request,
                                                          const SceneTextures& textures) {
    auto renderer = gpu::tryCreatePopulationRenderer(request, textures);
    if (!renderer) throw CommandFailure(renderer.error());
    return std::move(renderer).value();
}

std::unique_ptr<PopulationRenderer> createCommandRenderer(const gpu::RendererRequest& request,
                                                          const Preset& preset,
                                                          const std::filesystem::path& presetFile) {
    auto renderer = gpu::createPresetRenderer(request, preset, presetFile);
    if (!renderer) throw CommandFailure(renderer.error());
    return std::move(renderer).value();
}

nlohmann::ordered_json madeBy(const PopulationRenderer& renderer) {
    return {{"matevo", MATEVO_VERSION},
            {"backend", choiceName(kRenderBackends, renderer.backend())},
            {"device", renderer.name()}};
}

}  // namespace matevo::cli
