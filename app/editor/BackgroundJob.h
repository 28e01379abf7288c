#pragma once
// One job at a time on a worker thread, for the editor's long tasks ("Compare metrics", the
// Variants search): the UI thread starts it, polls busy() and progress() and takes the result;
// `onUpdate` (which must be thread-safe) wakes the UI whenever there is something to show. The
// job passes cancelToken() into core, cancelled when the editor closes. Nothing may escape the
// thread: an exception becomes the result's `error` (Result has a std::string `error`), shown
// in the window.
#include <atomic>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include "common/CancelToken.h"

namespace matevo::editor {

template <typename Result>
class BackgroundJob {
public:
    explicit BackgroundJob(std::function<void()> onUpdate) : onUpdate_(std::move(onUpdate)) {}
    ~BackgroundJob() {  // asks a running job to stop and waits for it
        cancel_.cancel();
        if (thread_.joinable()) thread_.join();
    }
    BackgroundJob(const BackgroundJob&) = delete;
    BackgroundJob& operator=(const BackgroundJob&) = delete;

    // Runs work() on the worker unless a job is running; returns whether it started. `what`
    // names the job in a failure ("the comparison" failed: ...).
    bool start(std::function<Result()> work, std::string what) {
        if (busy_.exchange(true)) return false;
        if (thread_.joinable()) thread_.join();  // the previous job has finished
        progress_.store(0.0f);
        thread_ = std::thread([this, work = std::move(work), what = std::move(what)] {
            Result result;
            try {
                result = work();
            } catch (const std::exception& error) {
                result = Result{};
                result.error = what + " failed: " + error.what();
            } catch (...) {
                result = Result{};
                result.error = what + " failed";
            }
            {
                std::lock_guard lock(mutex_);
                result_ = std::move(result);
            }
            busy_.store(false);
            onUpdate_();
        });
        return true;
    }

    bool busy() const { return busy_.load(); }
    float progress() const { return progress_.load(); }
    bool stopping() const { return cancel_.cancelled(); }
    const CancelToken& cancelToken() const { return cancel_; }
    // From the job: its progress in [0, 1], shown at once.
    void reportProgress(float progress) {
        progress_.store(progress);
        onUpdate_();
    }

    std::optional<Result> takeResult() {
        std::lock_guard lock(mutex_);
        return std::exchange(result_, std::nullopt);
    }
    bool hasResult() {
        std::lock_guard lock(mutex_);
        return result_.has_value();
    }

private:
    std::function<void()> onUpdate_;
    std::atomic<bool> busy_{false};
    CancelToken cancel_;
    std::atomic<float> progress_{0.0f};
    std::mutex mutex_;
    std::optional<Result> result_;
    std::thread thread_;
};

}  // namespace matevo::editor
