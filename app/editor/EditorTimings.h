#pragma once
// What `--report-timings` prints: the work per frame while idle and while the GA runs, and the
// time from a parameter change to the first updated grid on screen and to the finished run.
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace matevo::editor {

class EditorTimings {
public:
    using Clock = std::chrono::steady_clock;

    void addFrame(double milliseconds, bool evolving);
    // A frame was drawn while a script's `idle` action waited (an idle editor should draw none).
    void frameWhileScriptIdle() { ++framesWhileScriptIdle_; }
    void changeSubmitted(std::uint64_t jobId, Clock::time_point when);
    // Called when a frame showing results of `jobId` was presented.
    void resultsShown(std::uint64_t jobId, bool finished, Clock::time_point when);
    // One line of JSON with medians and sample counts.
    std::string report() const;

private:
    std::vector<double> idleFrames_;
    std::vector<double> evolvingFrames_;
    std::vector<double> changeToFirstGrid_;
    std::vector<double> changeToFinalGrid_;
    int framesWhileScriptIdle_ = 0;
    std::uint64_t pendingJob_ = 0;
    bool firstShown_ = false;
    Clock::time_point submittedAt_;
};

}  // namespace matevo::editor
