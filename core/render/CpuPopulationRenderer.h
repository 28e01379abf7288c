#pragma once
// The render interface on the CPU reference renderer (renderSphereCpu) and core/color's ΔE00
// and ꟻLIP: what runs without a usable Vulkan device, and what `--backend cpu` asks
// for.
#include <functional>
#include <optional>

#include "render/PopulationRenderer.h"

namespace matevo {

class CpuPopulationRenderer final : public PopulationRenderer {
public:
    // `cancelled` is asked between images; when it answers true the call ends with an Error
    // (a newer request superseded this one, e.g. in the editor).
    explicit CpuPopulationRenderer(SceneTextures textures, std::function<bool()> cancelled = {});

    std::string name() const override { return "CPU"; }
    RenderBackend backend() const override { return RenderBackend::Cpu; }
    Status setTextures(const SceneTextures& textures) override;
    Result<std::vector<Image>> render(std::span<const MaterialInstance> materials,
                                      const SceneSettings& scene, int size) override;
    Result<PopulationEvaluation> evaluate(const MaterialInstance& target,
                                          std::span<const MaterialInstance> candidates,
                                          const SceneSettings& scene, int size,
                                          const EvaluationOptions& options = {}) override;

private:
    bool cancelled() const { return cancelled_ && cancelled_(); }

    SceneTextures textures_;
    std::function<bool()> cancelled_;
    std::optional<TargetKey> targetKey_;
    Image target_;
};

}  // namespace matevo
