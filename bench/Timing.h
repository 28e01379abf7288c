#pragma once
// Median wall time of repeated runs. Medians, not means: the machines are shared and noisy.
#include <algorithm>
#include <chrono>
#include <vector>

namespace matevo::bench {

template <typename Work>
double medianMilliseconds(int repetitions, Work&& work) {
    std::vector<double> times;
    times.reserve(repetitions);
    for (int i = 0; i < repetitions; ++i) {
        auto start = std::chrono::steady_clock::now();
        work();
        auto stop = std::chrono::steady_clock::now();
        times.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
    }
    std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
    return times[times.size() / 2];
}

}  // namespace matevo::bench
