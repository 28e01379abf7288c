#include "ExportOutcome.h"

#include <cstdio>
#include <optional>
#include <utility>

#include "variants/DeliveredFiles.h"

namespace matevo::editor {
namespace {

std::string fixed2(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", value);
    return text;
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

// "#7": a variant by its index in the set, as the Variants window numbers its tiles.
std::string numbered(std::size_t index) {
    std::string text = "#";
    text += std::to_string(index);
    return text;
}

std::string fraction(std::size_t part, std::size_t whole) {
    return std::to_string(part) + "/" + std::to_string(whole);
}

// The delivered variant nearest to `member`, when there is another.
std::optional<std::size_t> nearestDelivered(const DeliveredSet& delivered, std::size_t member) {
    const std::vector<double>& distances = delivered.pairwise[member];
    std::optional<std::size_t> nearest;
    for (std::size_t other = 0; other < distances.size(); ++other)
        if (other != member && (!nearest || distances[other] < distances[*nearest]))
            nearest = other;
    return nearest;
}

// Why delivered variant `member` does not hold: "leaves the band (5.30)" or "is 1.61 from #3";
// empty when it holds. `withFigure`: with the distance (the lines give it already).
std::string whyNotDelivered(const DeliveredSet& delivered, std::size_t member,
                            const VariantRequest& request, bool withFigure = true) {
    const double toTarget = delivered.variants[member].deltaEToTarget;
    if (!request.band.contains(toTarget))
        return withFigure ? "leaves the band (" + fixed2(toTarget) + ")" : "leaves the band";
    const std::optional<std::size_t> nearest = nearestDelivered(delivered, member);
    if (!nearest || delivered.pairwise[member][*nearest] >= request.minApart) return {};
    return withFigure ? "is " + fixed2(delivered.pairwise[member][*nearest]) + " from " +
                            numbered(*nearest)
                      : "closer than " + number(request.minApart) + " to " + numbered(*nearest);
}

std::string bandInWords(const VariantRequest& request) {
    return "in band " + number(request.band.low) + "–" + number(request.band.high) +
           " and at least " + number(request.minApart) + " apart as delivered";
}

}  // namespace

std::string materialCount(std::size_t count) {
    return std::to_string(count) + (count == 1 ? " material" : " materials");
}

nlohmann::ordered_json deliveredReportJson(const ExportReport& report,
                                           const DeliveredSet& delivered,
                                           const VariantRequest& request) {
    nlohmann::ordered_json json = exportReportJson(report);
    std::size_t holding = 0;
    for (std::size_t i = 0; i < delivered.variants.size(); ++i) {
        nlohmann::ordered_json figures = deliveredFigures(delivered, i);
        const bool holds = deliveredHolds(delivered, i, request);
        figures["in_band_and_apart"] = holds;
        holding += holds ? 1 : 0;
        json["variants"][i]["delivered"] = std::move(figures);
    }
    nlohmann::ordered_json delivery{{"format", delivered.format},
                                    {"band", {request.band.low, request.band.high}},
                                    {"min_apart", request.minApart},
                                    {"in_band_and_apart", holding}};
    delivery.update(deliveryFigures(delivered));
    json["delivery"] = std::move(delivery);
    return json;
}

std::string describeExport(const ExportReport& report) {
    std::string text = "Exported " + materialCount(report.variants.size()) + " to " +
                       report.file.string() + " (" + std::string(toString(report.format)) +
                       "): fitted ΔE00 ";
    double sum = 0.0;
    std::size_t withinGoal = 0;
    for (std::size_t i = 0; i < report.variants.size(); ++i) {
        const ExportedVariant& variant = report.variants[i];
        text += (i > 0 ? ", " : "") + variant.name + ": " + fixed2(variant.deltaE.stats.mean);
        sum += variant.deltaE.stats.mean;
        withinGoal += withinExportGoal(variant, report.settings) ? 1 : 0;
    }
    if (!report.variants.empty()) text += "; mean " + fixed2(sum / double(report.variants.size()));
    return text + " (at " + std::to_string(report.settings.reportSize) +
           " px); within the goal of " + number(report.settings.fit.goalMeanDeltaE00) + ": " +
           fraction(withinGoal, report.variants.size());
}

std::string describeDeliveredExport(const ExportReport& report, const DeliveredSet& delivered,
                                    const VariantRequest& request) {
    const std::size_t count = delivered.variants.size();
    std::size_t withinGoal = 0, holding = 0;
    std::vector<std::string> failures;
    for (std::size_t i = 0; i < count; ++i) {
        withinGoal += delivered.withinGoal(i) ? 1 : 0;
        const std::string why = whyNotDelivered(delivered, i, request);
        if (why.empty())
            ++holding;
        else
            failures.push_back(numbered(i) + " " + why);
    }
    std::string text = "Exported " + std::to_string(count) +
                       (count == 1 ? " variant" : " variants") + " to " + report.file.string() +
                       " (" + std::string(toString(report.format)) + "): fitted ΔE00 within " +
                       number(delivered.goalDeltaE) + " for " + fraction(withinGoal, count) + "; " +
                       bandInWords(request) + ": " + fraction(holding, count);
    // The first three that do not hold, by name and why; the outcome window lists them all.
    for (std::size_t i = 0; i < failures.size() && i < 3; ++i)
        text += (i == 0 ? " — " : ", ") + failures[i];
    if (failures.size() > 3) text += ", …";
    return text;
}

ui::ExportOutcome exportOutcome(const ExportResult& result) {
    ui::ExportOutcome outcome;
    if (!result.error.empty() || !result.report) {
        outcome.failed = true;
        outcome.summary = "Export failed: " + result.error;
        return outcome;
    }
    const ExportReport& report = *result.report;
    if (!result.delivered) {
        outcome.summary = describeExport(report);
        for (const ExportedVariant& variant : report.variants) {
            const bool within = withinExportGoal(variant, report.settings);
            outcome.lines.push_back(
                {variant.name + ": fitted ΔE00 " + fixed2(variant.deltaE.stats.mean) +
                     (within
                          ? ", within the goal"
                          : ", past the goal of " + number(report.settings.fit.goalMeanDeltaE00)),
                 within});
        }
        return outcome;
    }
    const DeliveredSet& delivered = *result.delivered;
    const VariantRequest& request = *result.checkedFor;
    outcome.summary = describeDeliveredExport(report, delivered, request);
    const std::vector<double> nearest = nearestSiblings(delivered.pairwise);
    for (std::size_t i = 0; i < delivered.variants.size(); ++i) {
        const DeliveredVariant& variant = delivered.variants[i];
        const std::string why = whyNotDelivered(delivered, i, request, false);
        // By number, as the summary and the Variants window's tiles name them.
        std::string text = numbered(i) + ": fitted ΔE00 " + fixed2(variant.deltaEToMatevo) +
                           (delivered.withinGoal(i) ? " (within the goal)" : " (past the goal)") +
                           "; as delivered " + fixed2(variant.deltaEToTarget) + " from the target";
        if (delivered.variants.size() > 1) text += ", " + fixed2(nearest[i]) + " from the nearest";
        if (variant.attempt > 0) text += ", refitted";
        text += why.empty() ? "" : " — " + why;
        outcome.lines.push_back({text, why.empty() && delivered.withinGoal(i)});
    }
    return outcome;
}

std::filesystem::path exportReportFile(const std::filesystem::path& exported) {
    return exported.parent_path() / (exported.stem().string() + ".export.json");
}

}  // namespace matevo::editor
