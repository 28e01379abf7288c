#include "StepwiseOutput.h"

#include <filesystem>
#include <system_error>

#include "CommandLine.h"
#include "files/InputFile.h"

namespace matevo::cli {
namespace {

namespace fs = std::filesystem;

// `from`/`relative` as `to`/`relative`: a hard link, or a copy where links are not possible
// (another filesystem, or none at all). Files already there (the staging folder's marker) stay.
void linkInto(const fs::path& from, const fs::path& to, const fs::path& relative) {
    const fs::path source = from / relative, destination = to / relative;
    std::error_code error;
    if (fs::exists(destination, error)) return;
    fs::create_directories(destination.parent_path(), error);
    if (!error) fs::create_hard_link(source, destination, error);
    if (error) {
        error.clear();
        fs::copy_file(source, destination, error);
    }
    if (error)
        throw UsageError("--out: cannot keep " + displayPath(source) + ": " + error.message());
}

}  // namespace

void StepwiseOutput::keepCommitted() {
    const fs::path folder = output_->target();
    for (const auto& entry : fs::recursive_directory_iterator(folder))
        if (entry.is_regular_file())
            linkInto(folder, output_->staging(), fs::relative(entry.path(), folder));
}

void StepwiseOutput::step() {
    const Clock::time_point started = Clock::now();
    if (started - lastStep_ < 20 * lastStepCost_) return;
    if (auto committed = output_->commit(); !committed)
        throw CommandFailure(withContext(committed.error(), "--out"));
    const fs::path folder = output_->target();
    output_.reset();
    output_.emplace(claimOutputFolder(folder, true));
    keepCommitted();
    lastStep_ = Clock::now();
    lastStepCost_ = lastStep_ - started;
}

}  // namespace matevo::cli
