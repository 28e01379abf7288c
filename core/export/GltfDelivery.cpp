#include "export/GltfDelivery.h"

#include <algorithm>

#include "color/ImageDifference.h"
#include "common/ParallelFor.h"
#include "export/GltfRenderer.h"
#include "image/ImageFile.h"
#include "material/MaterialInstance.h"

namespace matevo {

GltfDelivery::GltfDelivery(const Genome& target, const MaterialFamily& family,
                           const std::array<double, 3>& baseKappa, SceneTextures textures,
                           const SceneSettings& scene, RenderGenomes belcourAtFitSize,
                           int outputSize, const ExportSettings& settings)
    : target_(target),
      family_(family),
      baseKappa_(baseKappa),
      textures_(std::move(textures)),
      scene_(scene),
      belcourAtFitSize_(std::move(belcourAtFitSize)),
      outputSize_(outputSize),
      settings_(settings) {}

Result<std::vector<Image>> GltfDelivery::render(std::span<const Genome> genomes, int attempt) {
    if (attempt < 0 || attempt >= kConversions)
        return internalError("glTF delivery: no conversion " + std::to_string(attempt));
    std::vector<Genome> missing;
    for (const Genome& genome : genomes)
        if (!conversions_.contains({genome.values, attempt}) &&
            std::find(missing.begin(), missing.end(), genome) == missing.end())
            missing.push_back(genome);
    if (!missing.empty()) {
        auto targets = belcourAtFitSize_(missing);
        if (!targets) return targets.error();
        if (targets->size() != missing.size())
            return internalError("glTF delivery: the renderer returned " +
                                 std::to_string(targets->size()) + " images for " +
                                 std::to_string(missing.size()) + " genomes");
        GltfFitSettings fitSettings = settings_.fit;
        std::vector<GltfMaterial> moreStarts;
        if (attempt > 0) {
            fitSettings.maxEvaluations *= 3;
            const auto targetFit = conversions_.find({target_.values, 0});
            if (targetFit != conversions_.end())
                moreStarts.push_back(targetFit->second.fit.material);
        }
        std::vector<Conversion> made(missing.size());
        // Each fit writes only its own entry, so the result does not depend on the threads.
        parallelForChunks(int(missing.size()), [&](int i) {
            const MaterialInstance material = materialOf(missing[i], family_, baseKappa_);
            made[i].fit = fitGltfMaterial(material, (*targets)[i], textures_, scene_, fitSettings,
                                          moreStarts);
            made[i].look = quantizeAsPng(
                renderGltfSphere(made[i].fit.material, textures_, scene_, outputSize_));
        });
        for (std::size_t i = 0; i < missing.size(); ++i)
            conversions_.emplace(Key{missing[i].values, attempt}, std::move(made[i]));
    }
    std::vector<Image> looks;
    for (const Genome& genome : genomes)
        looks.push_back(conversions_.at({genome.values, attempt}).look);
    return looks;
}

DeliveryFormat GltfDelivery::format() {
    return {
        "gltf",
        [this](std::span<const Genome> genomes, int attempt) { return render(genomes, attempt); },
        kConversions, settings_.fit.goalMeanDeltaE00};
}

Result<FittedSet> GltfDelivery::fittedSet(const std::vector<Member>& members) const {
    FittedSet set{settings_, textures_, {}};
    set.settings.reportSize = outputSize_;
    for (const Member& member : members) {
        const auto conversion = conversions_.find({member.genome.values, member.attempt});
        if (conversion == conversions_.end())
            return internalError("glTF delivery: " + member.name + " was never converted");
        auto difference = compareImages(conversion->second.look, member.belcour);
        if (!difference) return withContext(difference.error(), member.name);
        set.variants.push_back({member.name, conversion->second.fit, std::move(*difference),
                                member.belcour, conversion->second.look});
    }
    return set;
}

}  // namespace matevo
