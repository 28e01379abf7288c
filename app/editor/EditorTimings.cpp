#include "EditorTimings.h"

#include <algorithm>
#include <cstdio>

namespace matevo::editor {
namespace {

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

double millisecondsBetween(EditorTimings::Clock::time_point from,
                           EditorTimings::Clock::time_point to) {
    return std::chrono::duration<double, std::milli>(to - from).count();
}

}  // namespace

void EditorTimings::addFrame(double milliseconds, bool evolving) {
    (evolving ? evolvingFrames_ : idleFrames_).push_back(milliseconds);
}

void EditorTimings::changeSubmitted(std::uint64_t jobId, Clock::time_point when) {
    pendingJob_ = jobId;
    firstShown_ = false;
    submittedAt_ = when;
}

void EditorTimings::resultsShown(std::uint64_t jobId, bool finished, Clock::time_point when) {
    if (jobId != pendingJob_ || pendingJob_ == 0) return;
    if (!firstShown_) changeToFirstGrid_.push_back(millisecondsBetween(submittedAt_, when));
    firstShown_ = true;
    if (finished) {
        changeToFinalGrid_.push_back(millisecondsBetween(submittedAt_, when));
        pendingJob_ = 0;
    }
}

std::string EditorTimings::report() const {
    char line[512];
    std::snprintf(line, sizeof line,
                  "{\"frame_idle_ms\":%.2f,\"frame_idle_samples\":%zu,"
                  "\"frame_evolving_ms\":%.2f,\"frame_evolving_samples\":%zu,"
                  "\"change_to_first_grid_ms\":%.1f,\"change_to_final_grid_ms\":%.1f,"
                  "\"changes\":%zu,\"frames_while_script_idle\":%d}",
                  median(idleFrames_), idleFrames_.size(), median(evolvingFrames_),
                  evolvingFrames_.size(), median(changeToFirstGrid_), median(changeToFinalGrid_),
                  changeToFirstGrid_.size(), framesWhileScriptIdle_);
    return line;
}

}  // namespace matevo::editor
