#pragma once
// The one shape of the editor's background work: a thread that runs jobs one after another and
// hands their updates to the UI thread. Two policies:
//   LatestWins  a new job cancels the running one (its CancelToken) and replaces a queued one:
//               the GA run after each edit, the Scene window after each camera move;
//   OneAtATime  a job is refused while one is queued or running: Compare metrics, the variant
//               search, Export set….
// A job stops early through its CancelToken, which the work passes into core. Destroying the
// worker cancels the running job and joins the thread, so closing the editor ends every job.
// `onUpdate` (thread-safe) wakes the UI whenever the job publishes an update or progress.
// Nothing may escape the thread (std::terminate would lose the user's document): an exception
// becomes the update `failure` makes of its message, shown in the window.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include "common/CancelToken.h"

namespace matevo::editor {

enum class JobPolicy { LatestWins, OneAtATime };

template <typename Job, typename Update>
class BackgroundWorker {
public:
    // What a running job sees: its id and token, and where it reports.
    class Context {
    public:
        std::uint64_t jobId() const { return jobId_; }
        const CancelToken& token() const { return token_; }
        bool cancelled() const { return token_.cancelled(); }
        // Replaces any update not yet taken: the UI shows only the newest.
        void publish(Update update) { worker_.post(std::move(update)); }
        // In [0, 1]; the UI is woken to show it.
        void reportProgress(float progress) {
            worker_.progress_.store(progress);
            worker_.onUpdate_();
        }

    private:
        friend class BackgroundWorker;
        Context(BackgroundWorker& worker, std::uint64_t jobId, CancelToken token)
            : worker_(worker), jobId_(jobId), token_(std::move(token)) {}
        BackgroundWorker& worker_;
        std::uint64_t jobId_;
        CancelToken token_;
    };
    using Work = std::function<void(const Job&, Context&)>;
    // The update that reports a failed job: its id and what went wrong.
    using Failure = std::function<Update(std::uint64_t jobId, const std::string& message)>;

    BackgroundWorker(JobPolicy policy, std::function<void()> onUpdate, Work work, Failure failure)
        : policy_(policy),
          onUpdate_(std::move(onUpdate)),
          work_(std::move(work)),
          failure_(std::move(failure)),
          thread_([this] { loop(); }) {}
    ~BackgroundWorker() {
        cancel();
        thread_.join();
    }
    BackgroundWorker(const BackgroundWorker&) = delete;
    BackgroundWorker& operator=(const BackgroundWorker&) = delete;

    // Queues `job`; returns its id, or nothing when OneAtATime refused it.
    std::optional<std::uint64_t> submit(Job job) {
        std::uint64_t id = 0;
        {
            std::lock_guard lock(mutex_);
            if (stopping_) return std::nullopt;
            if (policy_ == JobPolicy::OneAtATime && (working_ || pending_)) return std::nullopt;
            running_.cancel();  // LatestWins: the running job is out of date
            pending_ = std::move(job);
            id = ++lastId_;
        }
        wake_.notify_one();
        return id;
    }
    // Cancels the running job and drops a queued one; no job starts after it. For closing:
    // every worker is cancelled first, then each is joined as it is destroyed.
    void cancel() {
        {
            std::lock_guard lock(mutex_);
            stopping_ = true;
            pending_.reset();
            running_.cancel();
        }
        wake_.notify_one();
    }

    // A job is queued or running (its last update may still wait to be taken).
    bool busy() const {
        std::lock_guard lock(mutex_);
        return working_ || pending_.has_value();
    }
    bool hasUpdate() const {
        std::lock_guard lock(mutex_);
        return latest_.has_value();
    }
    float progress() const { return progress_.load(); }
    // The running (or last) job's token, for a renderer made once for all jobs to ask.
    CancelToken runningToken() const {
        std::lock_guard lock(mutex_);
        return running_;
    }
    // The newest update not yet taken.
    std::optional<Update> take() {
        std::lock_guard lock(mutex_);
        return std::exchange(latest_, std::nullopt);
    }

private:
    void post(Update update) {
        {
            std::lock_guard lock(mutex_);
            latest_ = std::move(update);
        }
        onUpdate_();
    }

    void loop() {
        for (;;) {
            std::optional<Job> job;
            std::uint64_t id = 0;
            CancelToken token;
            {
                std::unique_lock lock(mutex_);
                wake_.wait(lock, [this] { return stopping_ || pending_.has_value(); });
                if (stopping_) return;
                job = std::exchange(pending_, std::nullopt);
                id = lastId_;
                running_ = token;
                working_ = true;
            }
            progress_.store(0.0f);
            Context context(*this, id, token);
            try {
                work_(*job, context);
            } catch (const std::exception& error) {
                post(failure_(id, error.what()));
            } catch (...) {
                post(failure_(id, "unknown failure"));
            }
            {
                std::lock_guard lock(mutex_);
                working_ = false;
            }
            onUpdate_();
        }
    }

    const JobPolicy policy_;
    std::function<void()> onUpdate_;
    Work work_;
    Failure failure_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<Job> pending_;
    std::optional<Update> latest_;
    CancelToken running_;
    std::uint64_t lastId_ = 0;
    bool working_ = false;
    bool stopping_ = false;
    std::atomic<float> progress_{0.0f};
    std::thread thread_;  // last: starts after everything it uses exists
};

}  // namespace matevo::editor
