#pragma once
// How many threads the CPU's parallel loops use: MATEVO_THREADS when it holds a whole number
// from 1 to 1024 (to run with fewer threads than cores, or to check that a result does not
// depend on the count), else the CPUs this process may use (its affinity mask and its cgroup's
// CPU quota, CgroupLimits.h), never the whole machine's when a scheduler gave it fewer.
#include <cstdlib>

#include "common/CgroupLimits.h"

namespace matevo {

inline unsigned workerThreadCount() {
    static const unsigned count = [] {
        if (const char* text = std::getenv("MATEVO_THREADS")) {
            char* end = nullptr;
            const long value = std::strtol(text, &end, 10);
            if (end != text && *end == '\0' && value >= 1 && value <= 1024) return unsigned(value);
        }
        return usableCpusOfProcess();
    }();
    return count;
}

}  // namespace matevo
