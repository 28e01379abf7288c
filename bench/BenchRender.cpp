#include <stdexcept>

#include "BenchReport.h"
#include "Timing.h"
#include "documents/PresetTextures.h"
#include "files/ResourcePaths.h"
#include "material/FgdTableCache.h"
#include "scene/SphereRenderer.h"

namespace matevo::bench {

void benchCpuRender(BenchReport& report) {
    // The default preset (validation metal) at its image size, tables already loaded.
    const auto presetFile = defaultPresetPath();
    if (!presetFile) throw std::runtime_error(presetFile.error().message);
    const auto loaded = loadPreset(*presetFile);
    if (!loaded) throw std::runtime_error(loaded.error().message);
    const Preset& preset = loaded->preset;
    const auto textures = loadSceneTextures(preset, *presetFile);
    if (!textures) throw std::runtime_error(textures.error().message);
    const MaterialInstance material{preset.target, preset.family, preset.baseKappa};
    const FgdTables& tables = defaultFgdTables();
    const int size = preset.scene.imageSize;
    const double milliseconds = medianMilliseconds(
        7, [&] { renderSphereCpu(material, *textures, preset.scene, size, tables); });
    report.push_back({"cpu_render_mpix_s", double(size) * size / 1e6 / (milliseconds / 1000.0),
                      "CPU reference renderer, default preset, all cores (Mpixel/s)"});
}

}  // namespace matevo::bench
