#pragma once
// CPU time used so far by the whole process (every thread: lavapipe's rasteriser and the workers
// too). On a machine shared with other jobs it moves far less than wall time, so benchmarks and
// the editor's `--report-timings` report it beside wall time.
#include <ctime>

namespace matevo {

inline double processCpuMilliseconds() {
    timespec now{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return double(now.tv_sec) * 1e3 + double(now.tv_nsec) * 1e-6;
}

}  // namespace matevo
