// The FGD/TIR tables in relative terms near eta = 1, where Fresnel energy is small and grows
// like (eta - 1)^2: a table can be close in absolute terms there and still wrong by a factor
// (the uniform eta axis once over-stated it x5.5 at 1.02). Each lookup is checked against
// direct integration (FgdIntegrals) with the bounds docs/belcour-decisions.md states.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "material/FgdIntegrals.h"
#include "material/FgdTableCache.h"

namespace matevo {
namespace {

constexpr double kEtasNearOne[] = {1.02, 1.05, 1.07, 1.1, 1.2, 1.5};

struct RelativeErrors {
    double sum = 0.0;
    double largest = 0.0;
    int count = 0;

    void add(double table, double direct) {
        const double error = std::abs(table - direct) / direct;
        sum += error;
        largest = std::max(largest, error);
        ++count;
    }
    double mean() const { return sum / count; }
};

// Coat and dielectric-base lookups: view cosines and roughnesses away from the grazing rim,
// where mu and alpha interpolation stays small in relative terms too.
TEST(FgdRelativeAccuracy, DielectricReflectanceNearIndexMatch) {
    const FgdTables& tables = defaultFgdTables();
    for (double eta : kEtasNearOne) {
        RelativeErrors errors;
        for (double mu : {0.25, 0.4, 0.55, 0.7, 0.85, 1.0})
            for (double alpha : {0.02, 0.05, 0.1, 0.2, 0.35, 0.5, 0.7, 0.9})
                errors.add(tables.reflectance(mu, alpha, eta, 0.0),
                           integrateFgd(mu, alpha, eta, 0.0));
        std::printf("FGD eta %.2f: relative error mean %.4f max %.4f\n", eta, errors.mean(),
                    errors.largest);
        EXPECT_LT(errors.mean(), 0.01) << eta;
        EXPECT_LT(errors.largest, 0.04) << eta;
    }
}

// The dielectric below the coat sees eta_2 / eta_1 > 1 at the transmitted cosine, which the
// coat keeps above the critical cosine sqrt(1 - 1 / eta_1^2); down to mu = 0.1 the relative
// error stays bounded.
TEST(FgdRelativeAccuracy, DielectricReflectanceAtLowCosines) {
    const FgdTables& tables = defaultFgdTables();
    RelativeErrors errors;
    for (double eta : kEtasNearOne)
        for (double mu : {0.1, 0.15, 0.2})
            for (double alpha : {0.05, 0.2, 0.5, 0.9})
                errors.add(tables.reflectance(mu, alpha, eta, 0.0),
                           integrateFgd(mu, alpha, eta, 0.0));
    std::printf("FGD mu 0.1-0.2: relative error mean %.4f max %.4f\n", errors.mean(),
                errors.largest);
    EXPECT_LT(errors.mean(), 0.03);
    EXPECT_LT(errors.largest, 0.1);
}

// TIR under a coat of index eta: light reaching the coat from below at cosines around the
// critical cosine sqrt(1 - 1 / eta^2), where the escape fraction falls from ~1 to 0.
TEST(FgdRelativeAccuracy, EscapeFractionAroundTheCriticalAngle) {
    const FgdTables& tables = defaultFgdTables();
    for (double eta : kEtasNearOne) {
        const double inside = 1.0 / eta;
        const double critical = std::sqrt(1.0 - inside * inside);
        double largest = 0.0, sum = 0.0;
        int count = 0;
        for (double offset : {-0.1, -0.05, 0.0, 0.05, 0.1}) {
            const double mu = std::clamp(critical + offset, 0.02, 1.0);
            for (double alpha : {0.05, 0.1, 0.2, 0.4, 0.7}) {
                const double error = std::abs(tables.escapeFraction(mu, alpha, inside) -
                                              integrateEscapeFraction(mu, alpha, inside));
                largest = std::max(largest, error);
                sum += error;
                ++count;
            }
        }
        std::printf("TIR eta %.2f (critical cosine %.3f): error mean %.4f max %.4f\n", eta,
                    critical, sum / count, largest);
        EXPECT_LT(sum / count, 0.02) << eta;
        EXPECT_LT(largest, 0.08) << eta;
    }
}

}  // namespace
}  // namespace matevo
