#include "export/NelderMead.h"

#include <algorithm>

namespace matevo {

namespace {

struct Vertex {
    std::vector<double> point;
    double value;
};

std::vector<double> along(const std::vector<double>& from, const std::vector<double>& to,
                          double t) {
    std::vector<double> result(from.size());
    for (std::size_t i = 0; i < from.size(); ++i) result[i] = from[i] + t * (to[i] - from[i]);
    return result;
}

}  // namespace

Minimum minimizeNelderMead(const std::function<double(const std::vector<double>&)>& objective,
                           const std::vector<double>& start, double step, int maxEvaluations,
                           double tolerance) {
    const std::size_t n = start.size();
    int evaluations = 0;
    auto evaluate = [&](std::vector<double> point) {
        ++evaluations;
        const double value = objective(point);
        return Vertex{std::move(point), value};
    };
    std::vector<Vertex> simplex;
    simplex.push_back(evaluate(start));
    for (std::size_t i = 0; i < n; ++i) {
        auto point = start;
        point[i] += step;
        simplex.push_back(evaluate(point));
    }
    auto byValue = [](const Vertex& a, const Vertex& b) { return a.value < b.value; };
    while (evaluations < maxEvaluations) {
        std::stable_sort(simplex.begin(), simplex.end(), byValue);
        if (simplex.back().value - simplex.front().value <= tolerance) break;
        std::vector<double> centroid(n, 0.0);
        for (std::size_t v = 0; v < n; ++v)
            for (std::size_t i = 0; i < n; ++i) centroid[i] += simplex[v].point[i] / double(n);
        Vertex& worst = simplex.back();
        const Vertex reflected = evaluate(along(centroid, worst.point, -1.0));
        if (reflected.value < simplex.front().value) {
            Vertex expanded = evaluate(along(centroid, worst.point, -2.0));
            worst = expanded.value < reflected.value ? std::move(expanded) : reflected;
        } else if (reflected.value < simplex[n - 1].value) {
            worst = reflected;
        } else {
            const bool outside = reflected.value < worst.value;
            Vertex contracted =
                evaluate(along(centroid, outside ? reflected.point : worst.point, 0.5));
            if (contracted.value < std::min(reflected.value, worst.value)) {
                worst = std::move(contracted);
            } else {
                for (std::size_t v = 1; v <= n; ++v)
                    simplex[v] = evaluate(along(simplex[0].point, simplex[v].point, 0.5));
            }
        }
    }
    const auto best = std::min_element(simplex.begin(), simplex.end(), byValue);
    return {best->point, best->value, evaluations};
}

}  // namespace matevo
