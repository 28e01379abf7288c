#include "ChoiceHelp.h"

#include <utility>

#include "color/ImageMetric.h"
#include "evolve/GaSettings.h"
#include "export/ExportSet.h"
#include "render/PopulationRenderer.h"
#include "scene/LightingChoice.h"

namespace matevo::cli {

std::string withChoiceNames(std::string_view help) {
    const std::pair<std::string_view, std::string> placeholders[] = {
        {"{distances}", joinChoiceNames(kDistanceMetrics, "|")},
        {"{image-metrics}", joinChoiceNames(kImageMetrics, "|")},
        {"{formats}", joinChoiceNames(kExportFormats, "|")},
        {"{backends}", joinChoiceNames(kRenderBackends, "|")},
        {"{lightings}", joinChoiceNames(kLightings, "|")},
    };
    std::string text(help);
    for (const auto& [placeholder, names] : placeholders)
        for (auto at = text.find(placeholder); at != std::string::npos;
             at = text.find(placeholder, at + names.size()))
            text.replace(at, placeholder.size(), names);
    return text;
}

}  // namespace matevo::cli
