#include "MemoryLimitWatch.h"

#include <new>
#include <optional>
#include <utility>

#include "CommandLine.h"
#include "StopSignals.h"
#include "common/ByteSize.h"
#include "common/MemoryBudget.h"
#include "common/MemoryWatch.h"

namespace matevo::cli {
namespace {

struct WatchedWork {
    explicit WatchedWork(std::string work)
        : what(std::move(work)), watch(stopToken(), memoryLimitBytes()) {}
    std::string what;
    MemoryWatch watch;
};

// The command's watch, from its estimate to its end (or the process's exit).
std::optional<WatchedWork>& watchedWork() {
    static std::optional<WatchedWork> work;
    return work;
}

// Stops the watch; throws the limit when it was passed.
void endWatch() {
    auto& work = watchedWork();
    if (!work) return;
    const auto resident = work->watch.exceeded();
    const std::string message =
        resident ? "memory limit " + describeBytes(work->watch.limitBytes()) + " exceeded by " +
                       work->what + " (resident " + describeBytes(*resident) + ")"
                 : std::string();
    work.reset();
    if (resident) throw CommandFailure(environmentError(message));
}

}  // namespace

void watchMemoryLimit(const std::string& what) {
    watchedWork().reset();
    watchedWork().emplace(what);
}

void sampleMemoryNow() {
    if (auto& work = watchedWork()) (void)work->watch.exceeded();
}

int runWithinMemoryLimit(int (*command)(CommandLine&), CommandLine& args) {
    int status = 0;
    try {
        status = command(args);
    } catch (const CommandFailure&) {
        endWatch();  // a stop at the limit surfaces as whatever the work failed with
        throw;
    } catch (const std::bad_alloc&) {
        endWatch();
        throw;
    }
    endWatch();
    return status;
}

}  // namespace matevo::cli
