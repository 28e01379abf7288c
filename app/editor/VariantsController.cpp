#include "VariantsController.h"

#include <utility>

#include "VariantsDisplay.h"
#include "experiment/Font.h"
#include "io/MaterialFile.h"
#include "io/OutputFolder.h"

namespace matevo::editor {
namespace {

gpu::RendererRequest variantsRenderer(const FeatureContext& context) {
    gpu::RendererRequest request;
    request.backend = context.backend;
    request.who = "matevo edit: Variants";
    request.device = &context.device;
    return request;
}

}  // namespace

VariantsController::VariantsController(const FeatureContext& context)
    : bridge_(context.bridge), worker_(context.wake, variantsRenderer(context)) {}

Status VariantsController::showResults(ui::EditorState& state) {
    ui::VariantsView& view = state.variants;
    view.running = worker_.busy();
    view.progress = worker_.progress();
    std::optional<VariantsResult> result = worker_.takeResult();
    if (!result) return Ok{};
    shown_ = std::move(result);
    return showSet(state);
}

Status VariantsController::showSet(ui::EditorState& state) {
    auto shown = showVariants(*shown_, bridge_, state.variants);
    if (!shown) return shown.error();
    images_ = std::move(shown).value();
    return Ok{};
}

void VariantsController::handleRequests(const ui::FrameRequests& requests,
                                        ui::EditorState& state) {
    const ui::VariantsActions& actions = requests.variants;
    ui::VariantsView& view = state.variants;
    VariantRequest request;
    request.count = view.count;
    request.band = {double(view.low), double(view.high)};
    request.minApart = double(view.minApart);
    request.seed = std::uint64_t(view.seed);
    if (view.hueVariety) request.kappaGenes = KappaGenes::On;
    if (actions.run) {
        // The kept bin is where a set starts: its materials join as they are.
        if (view.startFromKept) request.keep = keptGenomesOfFamily(state.preset);
        discarded_.clear();
        if (worker_.start({state.preset, state.presetPath, request})) view.running = true;
    }
    if (!shown_) return;
    VariantSet& set = shown_->set;
    if (actions.discard >= 0 && std::size_t(actions.discard) < set.variants.size()) {
        discarded_.push_back(set.variants[std::size_t(actions.discard)].genome);
        removeVariant(set, std::size_t(actions.discard));
        if (Status shown = showSet(state); !shown)
            state.status.post(shown.error().message, ui::StatusKind::Error);
    }
    if (actions.refill) {
        // The same target as the shown set, the variants shown kept, the discarded ones barred.
        for (const Variant& variant : set.variants) request.keep.push_back(variant.genome);
        request.exclude = discarded_;
        if (worker_.start({shown_->preset, state.presetPath, request})) view.running = true;
    }
    if (actions.save) saveSet(state);
}

void VariantsController::saveSet(ui::EditorState& state) {
    ui::VariantsView& view = state.variants;
    const VariantsResult& shown = *shown_;
    // One whole set in the folder: an earlier saved set there is replaced as a whole, a
    // folder holding files matevo did not write is refused.
    auto save = [&]() -> Status {
        auto output = OutputFolder::claim(view.savePath, true);
        if (!output) return output.error();
        auto font = Font::dejaVuSans();  // the contact sheet's
        if (!font) return font.error();
        if (auto written = writeVariantFiles(
                output->staging(),
                materialFromPreset(shown.preset, shown.presetFile, shown.preset.target,
                                   shown.preset.name),
                shown.set, variantReport(shown.preset, shown.run, shown.set), *font);
            !written)
            return Error{output->userFacing(written.error().message)};
        return output->commit();
    };
    const Status saved = save();
    view.summary = saved ? "Saved the set to " + view.savePath
                         : "Save set failed: " + saved.error().message;
    state.status.post(view.summary, saved ? ui::StatusKind::Info : ui::StatusKind::Error);
}

}  // namespace matevo::editor
