#include "color/Ciede2000.h"

#include "color/detail/ColorFormulas.h"
#include "color/detail/StdMath.h"

namespace matevo {

double ciede2000(const Lab& reference, const Lab& sample) {
    return formulas::ciede2000<double, formulas::StdMath>(reference.l, reference.a, reference.b,
                                                          sample.l, sample.a, sample.b);
}

}  // namespace matevo
