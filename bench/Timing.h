#pragma once
// Median wall time of repeated runs. Medians, not means: the machines are shared and noisy.
#include <algorithm>
#include <chrono>
#include <vector>

#include "common/ProcessCpuTime.h"

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

// Median wall time and median CPU time of the whole process (every thread, lavapipe's too):
// on a machine shared with other jobs the CPU time of a run varies far less than its wall time.
struct WallAndCpu {
    double wallMilliseconds = 0;
    double cpuMilliseconds = 0;
};

template <typename Work>
WallAndCpu medianWallAndCpu(int repetitions, Work&& work) {
    std::vector<double> cpuTimes;
    const double wall = medianMilliseconds(repetitions, [&] {
        const double start = processCpuMilliseconds();
        work();
        cpuTimes.push_back(processCpuMilliseconds() - start);
    });
    std::nth_element(cpuTimes.begin(), cpuTimes.begin() + cpuTimes.size() / 2, cpuTimes.end());
    return {wall, cpuTimes[cpuTimes.size() / 2]};
}

}  // namespace matevo::bench
