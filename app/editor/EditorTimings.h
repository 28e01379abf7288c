#pragma once
// What `--report-timings` prints: the work per frame while idle and while the GA runs, and the
// time from a parameter change to the first updated grid on screen and to the finished run.
// Beside each wall time, the process's CPU time over the same span (every thread: lavapipe's
// rasteriser and the workers too), which moves far less than wall time on a shared machine.
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace matevo::editor {

class EditorTimings {
public:
    using Clock = std::chrono::steady_clock;

    // A span's wall and process CPU time in milliseconds.
    struct Span {
        double wallMs = 0.0;
        double cpuMs = 0.0;
    };
    // Where a span starts: now, on both clocks.
    struct Mark {
        Clock::time_point wall;
        double cpuMs = 0.0;
    };
    static Mark now();
    static Span between(const Mark& from, const Mark& to);

    void addFrame(const Span& frame, bool evolving);
    // A frame was drawn while a script's `idle` action waited (an idle editor should draw none).
    void frameWhileScriptIdle() { ++framesWhileScriptIdle_; }
    // A frame was not drawn because it showed what the screen already did.
    void frameUnchanged() { ++framesUnchanged_; }
    void changeSubmitted(std::uint64_t jobId, const Mark& when);
    // Called when a frame showing results of `jobId` was presented.
    void resultsShown(std::uint64_t jobId, bool finished, const Mark& when);
    // One line of JSON with medians and sample counts.
    std::string report() const;

private:
    std::vector<Span> idleFrames_;
    std::vector<Span> evolvingFrames_;
    std::vector<Span> changeToFirstGrid_;
    std::vector<Span> changeToFinalGrid_;
    int framesWhileScriptIdle_ = 0;
    int framesUnchanged_ = 0;
    std::uint64_t pendingJob_ = 0;
    bool firstShown_ = false;
    Mark submittedAt_;
};

}  // namespace matevo::editor
