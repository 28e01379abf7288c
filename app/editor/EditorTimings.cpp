#include "EditorTimings.h"

#include <algorithm>
#include <cstdio>
#include <ctime>

namespace matevo::editor {
namespace {

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

double medianWall(const std::vector<EditorTimings::Span>& spans) {
    std::vector<double> values;
    for (const auto& span : spans) values.push_back(span.wallMs);
    return median(std::move(values));
}

double medianCpu(const std::vector<EditorTimings::Span>& spans) {
    std::vector<double> values;
    for (const auto& span : spans) values.push_back(span.cpuMs);
    return median(std::move(values));
}

}  // namespace

EditorTimings::Mark EditorTimings::now() {
    timespec cpu{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &cpu);
    return {Clock::now(), double(cpu.tv_sec) * 1e3 + double(cpu.tv_nsec) * 1e-6};
}

EditorTimings::Span EditorTimings::between(const Mark& from, const Mark& to) {
    return {std::chrono::duration<double, std::milli>(to.wall - from.wall).count(),
            to.cpuMs - from.cpuMs};
}

void EditorTimings::addFrame(const Span& frame, bool evolving) {
    (evolving ? evolvingFrames_ : idleFrames_).push_back(frame);
}

void EditorTimings::changeSubmitted(std::uint64_t jobId, const Mark& when) {
    pendingJob_ = jobId;
    firstShown_ = false;
    submittedAt_ = when;
}

void EditorTimings::resultsShown(std::uint64_t jobId, bool finished, const Mark& when) {
    if (jobId != pendingJob_ || pendingJob_ == 0) return;
    if (!firstShown_) changeToFirstGrid_.push_back(between(submittedAt_, when));
    firstShown_ = true;
    if (finished) {
        changeToFinalGrid_.push_back(between(submittedAt_, when));
        pendingJob_ = 0;
    }
}

std::string EditorTimings::report() const {
    char line[768];
    std::snprintf(line, sizeof line,
                  "{\"frame_idle_ms\":%.2f,\"frame_idle_samples\":%zu,"
                  "\"frame_evolving_ms\":%.2f,\"frame_evolving_samples\":%zu,"
                  "\"change_to_first_grid_ms\":%.1f,\"change_to_final_grid_ms\":%.1f,"
                  "\"changes\":%zu,\"frames_while_script_idle\":%d,"
                  "\"frame_idle_cpu_ms\":%.2f,\"frame_evolving_cpu_ms\":%.2f,"
                  "\"change_to_final_grid_cpu_ms\":%.1f,\"frames_unchanged\":%d}",
                  medianWall(idleFrames_), idleFrames_.size(), medianWall(evolvingFrames_),
                  evolvingFrames_.size(), medianWall(changeToFirstGrid_),
                  medianWall(changeToFinalGrid_), changeToFirstGrid_.size(),
                  framesWhileScriptIdle_, medianCpu(idleFrames_), medianCpu(evolvingFrames_),
                  medianCpu(changeToFinalGrid_), framesUnchanged_);
    return line;
}

}  // namespace matevo::editor
