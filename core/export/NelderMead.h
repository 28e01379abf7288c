#pragma once
// Derivative-free minimisation of a function of a few variables (Nelder and Mead 1965, with the
// usual coefficients: reflection 1, expansion 2, contraction 1/2, shrink 1/2). Deterministic: the
// same start gives the same path. Used to fit export parameters to a rendered image, where the
// objective (a mean CIEDE2000) has no useful gradient.
#include <functional>
#include <vector>

namespace matevo {

struct Minimum {
    std::vector<double> point;
    double value = 0.0;
    int evaluations = 0;
};

// Starts from a simplex around `start` (each coordinate offset by `step`) and stops after
// `maxEvaluations` or when the simplex's values agree to within `tolerance`.
Minimum minimizeNelderMead(const std::function<double(const std::vector<double>&)>& objective,
                           const std::vector<double>& start, double step, int maxEvaluations,
                           double tolerance = 1e-4);

}  // namespace matevo
