#pragma once
// Renders candidate tiles and their ΔE00 maps against the target, and remembers them across
// generations and across GA re-runs while the picture's inputs (target, family, kappa, scene,
// textures) stay the same. The best candidates mostly survive from one generation to the next,
// and a re-run with the same seed starts from much the same population, so most tiles of an
// update are already drawn. New tiles are drawn in one batch on the GPU (render + ΔE00 in one
// submission); without a usable Vulkan device, on the CPU reference renderer.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "color/ImageDifference.h"
#include "common/Image.h"
#include "common/Result.h"
#include "gpu/GpuContext.h"
#include "gpu/GpuPopulationEvaluator.h"
#include "io/Preset.h"
#include "scene/SceneTextures.h"

namespace matevo::editor {

struct CandidateTile {
    Image image;
    DeltaEMap deltaE;
};

class CandidateRenderCache {
public:
    // `useGpu` false keeps every render on the CPU (for comparison and machines whose Vulkan
    // driver misbehaves); `validation` runs the GPU context under the validation layer.
    CandidateRenderCache(int tileSize, int targetSize, std::size_t capacity, bool useGpu,
                         bool validation);
    ~CandidateRenderCache();

    // Serves `preset` from now on; forgets everything if the picture's inputs changed.
    Status prepare(const Preset& preset, const std::filesystem::path& presetFile);
    const Image& target() const { return target_; }
    // The tiles of `genomes`, in order; nullopt when `cancelled` said so between CPU renders.
    std::optional<std::vector<CandidateTile>> tiles(std::span<const Genome> genomes,
                                                    const std::function<bool()>& cancelled);
    // "GPU (llvmpipe)" or "CPU", for the status line.
    std::string backendName() const;
    // Validation warnings and errors from the GPU context (0 without validation or GPU).
    int validationMessages() const;

private:
    struct Entry {
        Genome genome;
        CandidateTile tile;
        std::uint64_t lastUse = 0;
    };
    bool drawsTheSame(const Preset& preset, const std::filesystem::path& presetFile) const;
    void createGpuEvaluator();
    Image renderOne(const Genome& genome, int size);
    bool drawOnGpu(const std::vector<Genome>& genomes);
    bool drawOnCpu(const std::vector<Genome>& genomes, const std::function<bool()>& cancelled);
    Entry* find(const Genome& genome);
    void evictBeyondCapacity();

    int tileSize_;
    int targetSize_;
    std::size_t capacity_;
    std::optional<Preset> preset_;  // what the cached pictures were drawn from
    std::filesystem::path presetFile_;
    SceneTextures textures_;
    Image target_;
    Image targetTile_;
    std::vector<Entry> entries_;
    std::uint64_t useCounter_ = 0;
    // The device must outlive the evaluator that renders on it.
    std::unique_ptr<gpu::GpuContext> gpu_;
    std::optional<gpu::GpuPopulationEvaluator> evaluator_;
};

}  // namespace matevo::editor
