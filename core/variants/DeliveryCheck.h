#pragma once
// The delivery check of a set (docs/variants.md, "Delivered sets"): the set chosen on matevo's
// Belcour render (chooseVariantSet) is checked again as its delivery format shows it — for glTF,
// the fitted glTF parameters rendered with the glTF BRDF (export/GltfDelivery.h). A variant whose
// delivered look leaves the band, or comes closer than minApart to another variant's, or
// whose conversion misses its own goal (DeliveryFormat::goalDeltaE), is converted again with
// more effort (a refit; past the goal, the refit is kept only when it holds within the goal);
// one whose conversions all leave the band or the spacing is replaced by the next
// member of the search's archive, in chooseVariantSet's order, that holds on both renders. So
// the set delivered meets the request on the Belcour render and in its delivery format.
#include <cstddef>
#include <string>
#include <vector>

#include "common/Image.h"
#include "common/Result.h"
#include "evolve/DeliveryFormat.h"
#include "evolve/RenderGenomes.h"
#include "genome/Genome.h"
#include "variants/VariantArchive.h"
#include "variants/VariantSearch.h"
#include "variants/VariantSet.h"

namespace matevo {

struct DeliveredVariant {
    Image image;                // the delivered look at the output size
    double deltaEToTarget = 0;  // mean ΔE00 to the target's delivered look
    double deltaEToMatevo = 0;  // mean ΔE00 to the variant's own Belcour render
    int attempt = 0;            // the conversion that holds (0: the first)
};

// The set's delivered looks, in the set's order.
struct DeliveredSet {
    std::string format;
    Image target;
    double targetToMatevo = 0;  // the target's conversion: delivered look vs Belcour render
    double goalDeltaE = 2.0;
    std::vector<DeliveredVariant> variants;
    std::vector<std::vector<double>> pairwise;  // mean ΔE00 between delivered looks
    double smallestPairwise = 0;
    std::size_t conversions = 0;  // delivered looks made (first attempts and refits)
    std::size_t refitted = 0;     // variants delivered by a conversion past the first
    std::size_t replaced = 0;     // members of the chosen set replaced from the archive

    bool withinGoal(std::size_t variant) const {
        return variants[variant].deltaEToMatevo <= goalDeltaE;
    }
};

struct DeliveredVariants {
    VariantSet set;  // the set delivered: on the Belcour render as chooseVariantSet's
    DeliveredSet delivered;
};

// Checks `chosen` (chooseVariantSet's set from `archive`) in `format`, refitting and refilling
// as above; `outputRender` as for chooseVariantSet (it renders refill candidates). Variants the
// user kept stay whatever their delivered look (by the first conversion that holds, else the
// first within the goal). An Error when rendering or converting failed.
Result<DeliveredVariants> checkDelivery(const VariantArchive& archive, VariantSet chosen,
                                        const VariantRequest& request, const Genome& target,
                                        const RenderGenomes& outputRender,
                                        const DeliveryFormat& format);

// `set` delivered as it is (the editor's Export set exports the user's set whole): every
// variant is delivered whatever its look, as kept variants are above, refitted when its first
// conversion leaves the band or the spacing or misses the goal; none is replaced. Which
// variants still hold as delivered is deliveredHolds'.
Result<DeliveredSet> deliverSetAsItIs(VariantSet set, const VariantRequest& request,
                                      const Genome& target, const DeliveryFormat& format);

// Whether delivered variant `member` lies in the band from the target's delivered look and at
// least minApart from every other delivered variant.
bool deliveredHolds(const DeliveredSet& delivered, std::size_t member,
                    const VariantRequest& request);

}  // namespace matevo
