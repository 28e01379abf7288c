#pragma once
// Median wall (and process CPU) times of repeated runs. Medians, not means: the machines are
// shared and noisy.
#include <algorithm>
#include <chrono>
#include <vector>

#include "common/ProcessCpuTime.h"

namespace matevo::bench {

inline double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

inline double median(std::vector<double> values) {
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
}

template <typename Work>
double medianMilliseconds(int repetitions, Work&& work) {
    std::vector<double> times;
    times.reserve(repetitions);
    for (int i = 0; i < repetitions; ++i) {
        const auto start = std::chrono::steady_clock::now();
        work();
        times.push_back(millisecondsSince(start));
    }
    return median(std::move(times));
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
    return {wall, median(std::move(cpuTimes))};
}

// Two kinds of work timed in turn (first second, second first, first second, ...), each at
// least `repetitions` times and until all of them together took `minimumMilliseconds`: for a
// ratio of the two in the same run. A change in the load of the shared machine then falls on
// both alike, neither always runs right after the other, and a call of a few milliseconds gets
// enough repetitions for a steady median.
struct AlternatingTimes {
    WallAndCpu first;
    WallAndCpu second;
};

template <typename First, typename Second>
AlternatingTimes alternatingMedians(int repetitions, double minimumMilliseconds, First&& first,
                                    Second&& second) {
    std::vector<double> wall[2], cpu[2];
    const auto time = [&](int which) {
        const double cpuStart = processCpuMilliseconds();
        const auto wallStart = std::chrono::steady_clock::now();
        if (which == 0)
            first();
        else
            second();
        wall[which].push_back(millisecondsSince(wallStart));
        cpu[which].push_back(processCpuMilliseconds() - cpuStart);
    };
    const auto start = std::chrono::steady_clock::now();
    for (int pair = 0; pair < repetitions || millisecondsSince(start) < minimumMilliseconds;
         ++pair) {
        time(pair % 2);
        time(1 - pair % 2);
    }
    return {{median(wall[0]), median(cpu[0])}, {median(wall[1]), median(cpu[1])}};
}

}  // namespace matevo::bench
