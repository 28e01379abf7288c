#include "fitness/RenderGenomesWith.h"

#include <span>
#include <utility>
#include <vector>

#include "material/MaterialInstance.h"

namespace matevo {

RenderGenomes renderGenomesWith(std::shared_ptr<PopulationRenderer> renderer,
                                const MaterialFamily& family, const std::array<double, 3>& kappa,
                                const SceneSettings& scene, int size) {
    return [renderer = std::move(renderer), family, kappa, scene,
            size](std::span<const Genome> genomes) {
        std::vector<MaterialInstance> materials;
        materials.reserve(genomes.size());
        for (const Genome& genome : genomes) materials.push_back(materialOf(genome, family, kappa));
        return renderer->render(materials, scene, size);
    };
}

}  // namespace matevo
