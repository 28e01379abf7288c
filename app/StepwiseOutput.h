#pragma once
// An output folder committed step by step (`matevo variants --block`): after each completed
// block the run so far replaces the folder, whole (files/OutputFolder.h), so a kill -9 or a
// scheduler's time limit leaves the completed blocks for a later run of the same request to
// keep (variants/ShareResume.h). The next staging folder starts from the committed files as
// hard links (copies where the filesystem has none): a step costs a link per file, not a copy.
#include <chrono>
#include <optional>

#include "files/OutputFolder.h"

namespace matevo::cli {

class StepwiseOutput {
public:
    // `output` is the run's claimed folder; each step replaces it with the next staging folder.
    explicit StepwiseOutput(std::optional<OutputFolder>& output) : output_(output) {}

    // Brings every file of the folder in place into the staging folder: what a resumed run
    // keeps (the folder only ever holds whole blocks and the set's own files).
    void keepCommitted();

    // Commits what the staging folder holds and starts the next one from it. Skipped while the
    // last step took more than a twentieth of the time since it: with thousands of files in
    // the folder, short blocks are committed a few at a time rather than relinked each time.
    void step();

private:
    using Clock = std::chrono::steady_clock;
    std::optional<OutputFolder>& output_;
    Clock::time_point lastStep_ = Clock::now();
    Clock::duration lastStepCost_{};
};

}  // namespace matevo::cli
