#include "color/PerceptualBand.h"

#include <limits>

#include "color/ViridisTable.h"

namespace matevo {
namespace {

struct BandInfo {
    double upperEdge;
    std::string_view rangeLabel;
    std::string_view description;
};

constexpr BandInfo kBandInfo[kPerceptualBandCount] = {
    {1.0, "<= 1", "not perceptible"},
    {2.0, "1-2", "perceptible through close observation"},
    {10.0, "2-10", "perceptible at a glance"},
    {49.0, "10-49", "colours more similar than opposite"},
    {std::numeric_limits<double>::infinity(), "> 49", "colours opposite"},
};

const BandInfo& infoOf(PerceptualBand band) { return kBandInfo[int(band)]; }

}  // namespace

PerceptualBand classifyDeltaE(double deltaE) {
    for (PerceptualBand band : kPerceptualBands)
        if (deltaE <= infoOf(band).upperEdge) return band;
    return PerceptualBand::kOpposite;  // NaN
}

double bandUpperEdge(PerceptualBand band) { return infoOf(band).upperEdge; }
std::string_view bandRangeLabel(PerceptualBand band) { return infoOf(band).rangeLabel; }
std::string_view bandDescription(PerceptualBand band) { return infoOf(band).description; }

std::array<float, 3> bandColorSrgb(PerceptualBand band) {
    const int last = int(kViridisSrgb.size()) - 1;
    return kViridisSrgb[std::size_t(int(band) * last / (kPerceptualBandCount - 1))];
}

}  // namespace matevo
