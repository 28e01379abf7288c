#pragma once
// What `matevo variants --deliver FORMAT --out DIR` adds to a set's files (VariantFiles.h):
//   DIR/delivered/target.png             the target's delivered look at the output size
//   DIR/delivered/variant_NNN.png        each variant's delivered look (DeliveryCheck.h)
// (and, written by the format's writer: for glTF DIR/delivered/set.glb and its export report
// DIR/delivered/export.json), and to the report: per variant its delivered measurements, and
// the delivered set's pairwise ΔE00.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/Result.h"
#include "variants/DeliveryCheck.h"
#include "variants/VariantSearch.h"

namespace matevo {

// DIR/delivered.
std::filesystem::path deliveredFolder(const std::filesystem::path& dir);

// Delivered variant `member`'s measurements: ΔE00 to the target's delivered look and to its
// nearest sibling's, ΔE00 to matevo's own render of it, whether that is within the format's
// goal, and whether a refit was needed.
nlohmann::ordered_json deliveredFigures(const DeliveredSet& delivered, std::size_t member);

// Variant `member` of the delivered set (variant `index` of the whole set) in the report: its
// delivered look's file and deliveredFigures.
nlohmann::ordered_json deliveredEntry(const DeliveredSet& delivered, std::size_t member,
                                      std::size_t index);

// The delivered set's measurements: the goal, the target's conversion, the pairwise ΔE00 of
// the delivered looks and its smallest entry, and the conversions, refits and replacements.
nlohmann::ordered_json deliveryFigures(const DeliveredSet& delivered);

// The report's "delivery": format, folder and deliveryFigures.
nlohmann::ordered_json deliveryJson(const DeliveredSet& delivered);

// "; delivered as gltf: 12 in band, smallest pairwise 2.10, 11 within the export goal".
std::string deliverySummary(const DeliveredSet& delivered, const VariantRequest& request);

// Writes DIR/delivered/target.png and variant_NNN.png, creating the folder.
Status writeDeliveredLooks(const std::filesystem::path& dir, const DeliveredSet& delivered);

}  // namespace matevo
