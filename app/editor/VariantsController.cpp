#include "VariantsController.h"

#include <algorithm>
#include <utility>

#include "EvolutionWorker.h"
#include "LightingPanel.h"
#include "VariantsDisplay.h"
#include "documents/MaterialFile.h"
#include "files/OutputFolder.h"
#include "image/Font.h"
#include "variants/VariantFiles.h"

namespace matevo::editor {
namespace {

gpu::RendererRequest variantsRenderer(const FeatureContext& context) {
    gpu::RendererRequest request;
    request.backend = context.backend;
    request.who = "matevo edit: Variants";
    request.device = &context.device;
    return request;
}

// The document's record of a set: its members and the target they were measured against.
SavedVariantSet savedSetOf(const VariantsResult& result) {
    SavedVariantSet saved{result.preset.family, result.preset.target, result.preset.baseKappa, {}};
    for (const Variant& variant : result.set.variants) saved.variants.push_back(variant.genome);
    return saved;
}

// The preset with the set's own target, family and kappa: what its figures are measured against.
Preset presetOfSet(Preset preset, const SavedVariantSet& set) {
    preset.family = set.family;
    preset.target = set.target;
    preset.baseKappa = set.baseKappa;
    return preset;
}

// Whether two inspector jobs draw the same pictures.
bool drawsTheSame(const VariantInspectJob& a, const VariantInspectJob& b) {
    return a.variant == b.variant && a.index == b.index && a.size == b.size &&
           a.madeFor.target == b.madeFor.target && a.madeFor.family == b.madeFor.family &&
           a.madeFor.baseKappa == b.madeFor.baseKappa && a.madeFor.scene == b.madeFor.scene &&
           a.madeFor.roughnessTexture == b.madeFor.roughnessTexture &&
           a.madeFor.baseColorTexture == b.madeFor.baseColorTexture &&
           a.presetFile == b.presetFile && a.heatmap.minDeltaE == b.heatmap.minDeltaE &&
           a.heatmap.maxDeltaE == b.heatmap.maxDeltaE;
}

// Whether `fewer` is `more` with some members left out, the rest in order.
bool isSubsequence(const std::vector<Genome>& fewer, const std::vector<Genome>& more) {
    std::size_t next = 0;
    for (const Genome& genome : more)
        if (next < fewer.size() && fewer[next] == genome) ++next;
    return next == fewer.size();
}

}  // namespace

VariantsController::VariantsController(const FeatureContext& context)
    : bridge_(context.bridge),
      inspector_(context.wake, variantsRenderer(context)),
      worker_(context.wake, variantsRenderer(context)) {}

VariantRequest VariantsController::request(const ui::VariantsView& view) const {
    VariantRequest request;
    request.count = view.count;
    request.band = {double(view.low), double(view.high)};
    request.minApart = double(view.minApart);
    request.seed = std::uint64_t(view.seed);
    if (view.hueVariety) request.kappaGenes = KappaGenes::On;
    // The editor's lighting first, then those the set must also hold under.
    request.lightings = ui::lightingsToHold(view.lighting, view.holdAlsoUnder);
    return request;
}

Status VariantsController::showResults(ui::EditorState& state) {
    ui::VariantsView& view = state.variants;
    view.running = worker_.busy();
    view.progress = worker_.progress();
    if (std::optional<VariantsResult> result = worker_.takeResult()) {
        if (!result->error.empty()) {
            // Shown as the window's summary; the document's set stays as it was.
            shown_.reset();
            shownFor_ = state.preset.variantSet;
            auto shown = showVariants(*result, bridge_, view);
            if (!shown) return shown.error();
            images_.clear();
            return Ok{};
        }
        shownFor_ = savedSetOf(*result);
        // A search's set becomes the document's (an edit: undone like any other).
        if (!result->measured) state.preset.variantSet = shownFor_;
        shown_ = std::move(result);
        if (Status shown = show(state); !shown) return shown;
    }
    if (Status followed = follow(state); !followed) return followed;
    return followInspection(state);
}

Status VariantsController::followInspection(ui::EditorState& state) {
    ui::VariantsView& view = state.variants;
    const auto& document = state.preset.variantSet;
    const bool selected =
        document && view.selected >= 0 && std::size_t(view.selected) < view.variants.size();
    if (!selected) {
        inspecting_.reset();
        view.inspection.reset();
        view.inspectionError.clear();
        inspectionImages_.clear();
        return Ok{};
    }
    VariantInspectJob wanted{presetOfSet(state.preset, *document),
                             state.presetPath,
                             view.variants[std::size_t(view.selected)].genome,
                             view.selected,
                             EvolutionWorker::kTargetSize,
                             {double(state.heatmap.minDeltaE), double(state.heatmap.maxDeltaE)}};
    if (!inspecting_ || !drawsTheSame(*inspecting_, wanted)) {
        view.inspectionError.clear();
        inspector_.start(wanted);
        inspecting_ = std::move(wanted);
    }
    std::optional<VariantInspectResult> result = inspector_.take();
    if (!result || result->variant != inspecting_->variant || result->index != inspecting_->index)
        return Ok{};
    if (!result->error.empty()) {
        view.inspectionError = result->error;
        return Ok{};
    }
    const std::vector<Image> pictures{result->target, result->render, result->heatmap};
    auto shown = bridge_.upload(pictures);
    if (!shown) return shown.error();
    inspectionImages_ = std::move(shown).value();
    view.inspection =
        ui::VariantInspection{result->variant,
                              result->index,
                              result->size,
                              result->deltaE.stats.mean,
                              inspectionImages_[0]->render(),
                              inspectionImages_[1]->render(),
                              inspectionImages_[2]->render(),
                              std::make_shared<const Image>(std::move(result->target)),
                              std::make_shared<const Image>(std::move(result->render)),
                              std::make_shared<const ErrorMap>(std::move(result->deltaE))};
    return Ok{};
}

bool VariantsController::inspectionSettled(const ui::VariantsView& view) const {
    if (!inspecting_) return true;
    if (inspector_.busy()) return false;
    return !view.inspectionError.empty() ||
           (view.inspection && view.inspection->genome == inspecting_->variant &&
            view.inspection->index == inspecting_->index);
}

Status VariantsController::follow(ui::EditorState& state) {
    const std::optional<SavedVariantSet>& document = state.preset.variantSet;
    if (worker_.busy() || document == shownFor_) return Ok{};
    ui::VariantsView& view = state.variants;
    if (!document || document->variants.empty()) {
        shown_.reset();
        shownFor_ = document;
        images_.clear();
        view.variants.clear();
        view.pairwise.clear();
        view.target = nullptr;
        view.selected = -1;
        view.summary.clear();
        return Ok{};
    }
    // Members discarded: the measured set loses them, nothing is rendered.
    if (shown_ && shownFor_ && document->family == shownFor_->family &&
        document->target == shownFor_->target && document->baseKappa == shownFor_->baseKappa &&
        isSubsequence(document->variants, shownFor_->variants)) {
        VariantSet& set = shown_->set;
        for (std::size_t i = set.variants.size(); i-- > 0;)
            if (std::find(document->variants.begin(), document->variants.end(),
                          set.variants[i].genome) == document->variants.end()) {
                discarded_.push_back(set.variants[i].genome);
                removeVariant(set, i);
                // The delivered figures were the whole set's: its spacing is no longer theirs.
                shown_->delivered.reset();
            }
        shownFor_ = document;
        return show(state);
    }
    VariantRequest measuring = request(view);
    measuring.count = int(document->variants.size());
    if (worker_.start({presetOfSet(state.preset, *document), state.presetPath, measuring,
                       document->variants, false}))
        view.running = true;
    return Ok{};
}

Status VariantsController::show(ui::EditorState& state) {
    auto shown = showVariants(*shown_, bridge_, state.variants);
    if (!shown) return shown.error();
    images_ = std::move(shown).value();
    return Ok{};
}

void VariantsController::handleRequests(const ui::FrameRequests& requests, ui::EditorState& state) {
    const ui::VariantsActions& actions = requests.variants;
    ui::VariantsView& view = state.variants;
    if (actions.run) {
        VariantRequest fresh = request(view);
        // The kept bin is where a set may start: its materials join as they are.
        if (view.startFromKept) fresh.keep = keptGenomesOfFamily(state.preset);
        discarded_.clear();
        if (worker_.start(
                {state.preset, state.presetPath, fresh, std::nullopt, view.holdAsDelivered}))
            view.running = true;
    }
    auto& document = state.preset.variantSet;
    if (!document) return;
    if (actions.remeasure) {
        // The same members against the present target: an edit of the document, which
        // follow() then measures.
        document->family = state.preset.family;
        document->target = state.preset.target;
        document->baseKappa = state.preset.baseKappa;
    }
    if (actions.refill) {
        // The set's members kept, the discarded ones barred; for the set's own target, or for
        // the present one when the set was made for another.
        VariantRequest refill = request(view);
        refill.keep = document->variants;
        refill.exclude = discarded_;
        const Preset preset = variantSetMadeForAnotherTarget(state.preset)
                                  ? state.preset
                                  : presetOfSet(state.preset, *document);
        if (worker_.start({preset, state.presetPath, refill, std::nullopt, view.holdAsDelivered}))
            view.running = true;
    }
    if (actions.save) saveFolder(state);
}

void VariantsController::saveFolder(ui::EditorState& state) {
    ui::VariantsView& view = state.variants;
    if (!shown_ || shownFor_ != state.preset.variantSet) {
        state.status.post("Save as folder: the set is still being measured",
                          ui::StatusKind::Warning);
        return;
    }
    const VariantsResult& shown = *shown_;
    auto save = [&]() -> Status {
        // One whole set in the folder: an earlier saved set there is replaced as a whole, a
        // folder holding files matevo did not write is refused.
        auto output = OutputFolder::claim(view.savePath, true);
        if (!output) return output.error();
        auto font = Font::dejaVuSans();  // the contact sheet's
        if (!font) return font.error();
        return saveVariantFolder(*output,
                                 materialFromPreset(shown.preset, shown.presetFile,
                                                    shown.preset.target, shown.preset.name),
                                 shown.set, variantReport(shown.preset, shown.run, shown.set),
                                 *font, state.heatmap.metric);
    };
    const Status saved = save();
    view.summary = saved ? "Saved the set to " + view.savePath
                         : "Save as folder failed: " + saved.error().message;
    state.status.post(view.summary, saved ? ui::StatusKind::Info : ui::StatusKind::Error);
}

}  // namespace matevo::editor
