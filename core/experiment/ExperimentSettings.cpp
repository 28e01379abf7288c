#include "experiment/ExperimentSettings.h"

namespace matevo {

std::vector<GaSize> paperSweep(const MaterialFamily& family) {
    std::vector<GaSize> sizes = {{50, 5}, {100, 10}, {300, 20}};
    if (family.hasMedium) sizes.push_back({500, 50});
    return sizes;
}

}  // namespace matevo
