#include "BenchReport.h"
#include "Timing.h"
#include "material/FgdTableCache.h"
#include "scene/SphereRenderer.h"

namespace matevo::bench {

void benchCpuRender(BenchReport& report) {
    // Validation metal at the default 256^2 (2 x 2 subsamples per pixel), tables already loaded.
    MaterialInstance material;
    material.family = {Coat::Clearcoat, Base::Conductor, false, TexturedLayer::None};
    material.genome[kEta1] = 1.2;
    material.genome[kEta2] = 0.8;
    material.genome[kAlpha1] = 0.03;
    material.genome[kAlpha2] = 0.1;
    material.baseKappa = {3.1, 2.9, 2.8};
    const SceneSettings scene;
    const FgdTables& tables = defaultFgdTables();
    const double milliseconds = medianMilliseconds(
        7, [&] { renderSphereCpu(material, {}, scene, scene.imageSize, tables); });
    const double megapixels = double(scene.imageSize) * scene.imageSize / 1e6;
    report.push_back({"cpu_render_mpix_s", megapixels / (milliseconds / 1000.0),
                      "CPU reference renderer, validation metal 256^2, all cores (Mpixel/s)"});
}

}  // namespace matevo::bench
