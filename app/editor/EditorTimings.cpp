#include "EditorTimings.h"

#include <algorithm>
#include <cstdio>

#include "common/ProcessCpuTime.h"
#include "gpu/Device.h"

namespace matevo::editor {
namespace {

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

// The median of one clock's readings (`clock`: &Span::wallMs or &Span::cpuMs).
double median(const std::vector<EditorTimings::Span>& spans, double EditorTimings::Span::*clock) {
    std::vector<double> values;
    for (const auto& span : spans) values.push_back(span.*clock);
    return median(std::move(values));
}

}  // namespace

EditorTimings::Mark EditorTimings::now() { return {Clock::now(), processCpuMilliseconds()}; }

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
                  "\"change_to_final_grid_cpu_ms\":%.1f,\"frames_unchanged\":%d,"
                  "\"vulkan_devices\":%d}",
                  median(idleFrames_, &Span::wallMs), idleFrames_.size(),
                  median(evolvingFrames_, &Span::wallMs), evolvingFrames_.size(),
                  median(changeToFirstGrid_, &Span::wallMs),
                  median(changeToFinalGrid_, &Span::wallMs), changeToFirstGrid_.size(),
                  framesWhileScriptIdle_, median(idleFrames_, &Span::cpuMs),
                  median(evolvingFrames_, &Span::cpuMs), median(changeToFinalGrid_, &Span::cpuMs),
                  framesUnchanged_, gpu::logicalDevicesCreated());
    return line;
}

}  // namespace matevo::editor
