#pragma once
// The render interface on the CPU reference renderer (renderSphereCpu) and core/color's ΔE00
// and ꟻLIP: what runs without a usable Vulkan device, and what `--backend cpu` asks
// for.
#include <optional>

#include "common/CancelToken.h"
#include "render/PopulationRenderer.h"

namespace matevo {

class CpuPopulationRenderer final : public PopulationRenderer {
public:
    // `cancel` is checked between images; once it is cancelled a call ends with
    // cancelledError() (e.g. the editor's job was superseded or the editor closes).
    explicit CpuPopulationRenderer(SceneTextures textures, CancelToken cancel = {});

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
    SceneTextures textures_;
    CancelToken cancel_;
    std::optional<TargetKey> targetKey_;
    Image target_;
};

}  // namespace matevo
