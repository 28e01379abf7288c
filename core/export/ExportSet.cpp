#include "export/ExportSet.h"

#include <cctype>

#include "documents/PresetTextures.h"
#include "export/GltfRenderer.h"
#include "export/GltfWriter.h"
#include "export/MaterialXWriter.h"
#include "files/AtomicFile.h"

namespace matevo {

std::optional<ExportFormat> parseExportFormat(std::string_view text) {
    return parseChoice(kExportFormats, text);
}

std::string_view toString(ExportFormat format) { return choiceName(kExportFormats, format); }

std::string fileExtension(ExportFormat format) {
    std::string extension = ".";
    extension += toString(format);
    return extension;
}

std::string exportExtensionsInWords() {
    std::vector<std::string> extensions;
    for (const auto& format : kExportFormats) extensions.push_back(fileExtension(format.value));
    return inWords(extensions);
}

std::string exportFileStem(std::string_view name) {
    std::string stem;
    for (unsigned char c : name) stem += std::isalnum(c) || c == '-' || c == '_' ? char(c) : '_';
    return stem;
}

std::optional<ExportFormat> exportFormatOfFile(const std::filesystem::path& file) {
    for (const auto& format : kExportFormats)
        if (file.extension() == fileExtension(format.value)) return format.value;
    return std::nullopt;
}

bool withinExportGoal(const ExportedVariant& variant, const ExportSettings& settings) {
    return variant.deltaE.stats.mean <= settings.fit.goalMeanDeltaE00;
}

Result<FittedSet> fitForExport(const std::vector<MaterialFile>& materials,
                               PopulationRenderer& belcour, const ExportSettings& settings,
                               const ExportProgress& progress, const CancelToken& cancel) {
    if (materials.empty()) return badInput("nothing to export");
    const MaterialFile& first = materials.front();
    for (const auto& material : materials)
        if (material.roughnessTexture != first.roughnessTexture ||
            material.baseColorTexture != first.baseColorTexture)
            return badInput(material.name + ": its textures differ from " + first.name +
                            "'s; export the materials of one preset at a time");
    auto textures = loadSceneTextures(first, first.name);
    if (!textures) return textures.error();

    if (auto status = belcour.setTextures(*textures); !status) return status.error();

    FittedSet set{settings, std::move(*textures), {}};
    for (std::size_t i = 0; i < materials.size(); ++i) {
        if (cancel.cancelled()) return cancelledError("export stopped");
        const MaterialFile& material = materials[i];
        const auto renderAt = [&](int size) {
            return belcour.render(std::span(&material.material, 1), material.scene, size);
        };
        auto target = renderAt(settings.fit.imageSize);
        if (!target) return withContext(target.error(), material.name);
        GltfFit fit = fitGltfMaterial(material.material, target->front(), set.textures,
                                      material.scene, settings.fit);
        auto reference = renderAt(settings.reportSize);
        if (!reference) return withContext(reference.error(), material.name);
        const Image approximation =
            renderGltfSphere(fit.material, set.textures, material.scene, settings.reportSize);
        auto difference = compareImages(approximation, reference->front());
        if (!difference) return withContext(difference.error(), material.name);
        set.variants.push_back({material.name, std::move(fit), std::move(*difference),
                                std::move(reference->front()), approximation});
        if (progress) progress(i + 1, materials.size());
    }
    return set;
}

Result<ExportReport> writeExport(const FittedSet& set, ExportFormat format,
                                 const std::filesystem::path& file, const GltfAsset& asset) {
    if (format == ExportFormat::MaterialX && asset.arrangement != GltfArrangement::Spheres)
        return badInput(file.string() + ": MaterialX holds materials only; a " +
                        std::string(toString(asset.arrangement)) + " arrangement needs glTF");
    std::vector<NamedGltfMaterial> materials;
    for (const auto& variant : set.variants)
        materials.push_back({variant.name, variant.fit.material});
    // Temporary files of an export killed earlier (files/AtomicFile.h).
    removeStaleTemporaryFilesBeside(file);
    const Status written = format == ExportFormat::MaterialX
                               ? writeMaterialX(materials, set.textures, file)
                               : writeGltf(materials, set.textures, file, asset);
    if (!written) return written.error();
    return ExportReport{format, asset.arrangement, file, set.settings, set.variants};
}

Result<ExportReport> exportMaterials(const std::vector<MaterialFile>& materials,
                                     PopulationRenderer& belcour, ExportFormat format,
                                     const std::filesystem::path& file,
                                     const ExportSettings& settings, const ExportProgress& progress,
                                     const GltfAsset& asset, const CancelToken& cancel) {
    auto set = fitForExport(materials, belcour, settings, progress, cancel);
    if (!set) return set.error();
    if (cancel.cancelled()) return cancelledError("export stopped");  // during the last fit
    return writeExport(*set, format, file, asset);
}

std::string_view toString(GltfArrangement arrangement) {
    switch (arrangement) {
        case GltfArrangement::Spheres:
            return "spheres";
        case GltfArrangement::MaterialVariants:
            return "variants";
        case GltfArrangement::Instances:
            return "instances";
    }
    return "spheres";
}

namespace {

nlohmann::ordered_json gltfParameters(const GltfMaterial& m) {
    // As the file has them: values that do not act on the material are left out.
    nlohmann::ordered_json json = {
        {"base_color", m.baseColor}, {"metallic", m.metallic}, {"roughness", m.roughness}};
    if (iorActs(m)) json["ior"] = m.ior;
    if (specularActs(m)) {
        json["specular"] = m.specular;
        json["specular_color"] = m.specularColor;
    }
    json["clearcoat"] = m.clearcoat;
    json["clearcoat_roughness"] = m.clearcoatRoughness;
    json["base_color_texture"] = m.baseColorTextured;
    json["roughness_texture"] = m.roughnessTextured;
    json["clearcoat_roughness_texture"] = m.clearcoatRoughnessTextured;
    if (m.roughnessTextured || m.clearcoatRoughnessTextured)
        json["roughness_texel_scale"] = m.roughnessTexelScale;
    return json;
}

}  // namespace

nlohmann::ordered_json exportReportJson(const ExportReport& report) {
    nlohmann::ordered_json variants = nlohmann::ordered_json::array();
    double sum = 0.0;
    for (const auto& variant : report.variants) {
        const ErrorStats& stats = variant.deltaE.stats;
        sum += stats.mean;
        variants.push_back({{"name", variant.name},
                            {"gltf", gltfParameters(variant.fit.material)},
                            {"mean_de00", stats.mean},
                            {"max_de00", stats.max},
                            {"p95_de00", stats.p95},
                            {"fit_mean_de00", variant.fit.meanDeltaE00},
                            {"within_goal", withinExportGoal(variant, report.settings)},
                            {"fit_renders", variant.fit.evaluations}});
    }
    return {{"format", toString(report.format)},
            {"arrangement", toString(report.arrangement)},
            {"file", report.file.string()},
            {"report_size", report.settings.reportSize},
            {"fit_size", report.settings.fit.imageSize},
            {"goal_mean_de00", report.settings.fit.goalMeanDeltaE00},
            {"mean_de00", report.variants.empty() ? 0.0 : sum / double(report.variants.size())},
            {"variants", std::move(variants)}};
}

}  // namespace matevo
