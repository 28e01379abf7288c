#pragma once
// What `matevo variants` reports and writes, as functions of their own so that other commands
// (sharded runs and their merge) and the editor's "Save set" produce the same files:
//   DIR/report.json                       the report (variantReport)
//   DIR/target.png                        the target at the output size
//   DIR/target.json                       the target as a material file
//   DIR/textures/                         the textures the materials use, so that the folder
//                                         can be moved (documents/CarriedTextures.h)
//   DIR/contact_sheet.png                 the target and the set side by side
//   DIR/variants/variant_NNN.json         one material each, read by `render --genome`
//   DIR/variants/variant_NNN.png          its render at the output size
//   DIR/variants/variant_NNN_heatmap.png  its per-pixel ΔE00 against the target, 0-10 viridis
//                                         (or LDR-ꟻLIP, 0-1 magma)
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "color/ImageMetric.h"
#include "common/Image.h"
#include "common/Result.h"
#include "documents/MaterialFile.h"
#include "documents/Preset.h"
#include "evolve/RenderGenomes.h"
#include "files/OutputFolder.h"
#include "image/Font.h"
#include "render/LightingScenes.h"
#include "variants/DeliveryCheck.h"
#include "variants/VariantSearch.h"
#include "variants/VariantSet.h"

namespace matevo {

// How a set was made, for the report.
struct VariantRun {
    VariantRequest request;
    int size = 256;               // output resolution
    int fitnessSize = 64;         // the search's resolution
    std::size_t evaluations = 0;  // fitness-resolution renders
    std::size_t archived = 0;     // candidates the search held at its end
    double closestDeltaE = 0;     // the render nearest the band the search saw
    double wallSeconds = 0;
    // What rendered it, {"matevo": version, "backend", "device"}; null when not known.
    nlohmann::ordered_json madeBy;
};

// The renders as the written PNG files will hold them (quantizeAsPng), so that a set checked on
// them reports the figures `matevo compare` finds in its files.
RenderGenomes asStoredInPng(RenderGenomes render);

// Renders under each of `lit`'s lightings (one RenderGenomes each, LightingMeasure.h) at
// size x size, as stored in PNG files (asStoredInPng): what a variant search is given.
LightingRenders renderUnderEachLighting(const std::vector<LitScene>& lit,
                                        const MaterialFamily& family,
                                        const std::array<double, 3>& kappa, int size);

// "variant_007": the index in the whole set, with three digits, or as many as the last index
// of a set of `count` needs (a set of 1001 to 10000 variants: "variant_0007").
std::string variantStem(std::size_t index, std::size_t count = 0);

// One variant's entry in a report: its index in the whole set, its files, ΔE00 to the target
// and to its nearest sibling (`nearest`, VariantSet::nearestSibling), with named lightings the
// same per lighting ("de00_by_lighting"), kept or not, genome (and its own kappa when it
// carries kappa genes). `member` is its place in `set`.
nlohmann::ordered_json variantEntry(const Preset& preset, const VariantSet& set, std::size_t member,
                                    std::size_t index, std::size_t count,
                                    const std::vector<double>& nearest);

// The request as a report states it: count, band, distance, seed, hue variety, the two image
// sizes and the lightings when they are named.
nlohmann::ordered_json requestJson(const VariantRun& run);

// A set's pairwise ΔE00 matrix under each named lighting, keyed by its name in the request's
// order ("pairwise_de00_by_lighting").
nlohmann::ordered_json pairwiseByLighting(const VariantSet& set);

// The report: request, what made it (when known), per variant (file, ΔE00 to the target, to its
// nearest sibling, genome), the pairwise ΔE00 matrix (and with named lightings one per
// lighting), the smallest pairwise distance under any lighting, evaluations, wall time, seed,
// and whether the request was met with a one-line summary. The unnamed figures are those of the
// first lighting, the one the images show. With `delivered` (a set checked in its delivery
// format, DeliveryCheck.h), each variant also carries "delivered" (DeliveredFiles.h), the report
// "delivery", and the summary says how the delivered set holds.
nlohmann::ordered_json variantReport(const Preset& preset, const VariantRun& run,
                                     const VariantSet& set,
                                     const DeliveredSet* delivered = nullptr);

// "12 of 12 variants in band 2-5, at least 2 apart (smallest pairwise 2.31), 412 evaluations"
// or, when short, what was achieved.
std::string variantSummary(const VariantRun& run, const VariantSet& set);

// The target (top left) and the variants in rows, each labelled with its index (the set's
// members are the variants firstIndex, firstIndex + 1, … of a whole of `count`), its ΔE00 to
// the target and to its nearest sibling, on a dark background, in `font` (DejaVu Sans,
// image/Font.h: loaded by the caller before the search, so that a missing font is found
// out before the work rather than when the files are written).
Image contactSheet(const VariantSet& set, const Font& font, std::size_t firstIndex = 0,
                   std::size_t count = 0);

// The material file of variant `index` of a whole of `count`: `target` (the preset's target as a
// material file, documents/MaterialFile.h: family, kappa, textures, scene) with the variant's
// genome and name.
MaterialFile variantMaterial(const MaterialFile& target, const Variant& variant, std::size_t index,
                             std::size_t count = 0);

// DIR/target.json: the target as a material file (export shows it as the default material).
std::filesystem::path targetMaterialFile(const std::filesystem::path& dir);

// Writes the set's members as variants firstIndex, firstIndex + 1, … of a whole of `count`:
// DIR/variants/variant_NNN.json, .png and _heatmap.png, creating DIR/variants, with the target's
// material file and the textures they all use.
Status writeVariantMembers(const std::filesystem::path& dir, const MaterialFile& target,
                           const VariantSet& set, std::size_t firstIndex, std::size_t count,
                           ImageMetric heatmapMetric);

// Writes every file listed above (atomically, each one), creating the folders; an Error names
// the file that could not be written. Heatmaps of `heatmapMetric`. `target` as for
// variantMaterial, `font` as for contactSheet.
Status writeVariantFiles(const std::filesystem::path& dir, const MaterialFile& target,
                         const VariantSet& set, const nlohmann::ordered_json& report,
                         const Font& font, ImageMetric heatmapMetric = ImageMetric::DeltaE00);

// A whole set into a claimed output folder: every file above written into its staging folder,
// then put in place of the folder (OutputFolder::commit). The one way a set becomes a folder:
// `matevo variants --out` and the editor's "Save as folder…" both write through it. An Error
// names the file in the folder the user asked for.
Status saveVariantFolder(OutputFolder& output, const MaterialFile& target, const VariantSet& set,
                         const nlohmann::ordered_json& report, const Font& font,
                         ImageMetric heatmapMetric);

}  // namespace matevo
