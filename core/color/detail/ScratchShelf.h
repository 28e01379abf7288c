#pragma once
// Scratch objects kept from call to call. A fresh buffer of a megabyte costs hundreds of page
// faults when first written, and glibc hands freed memory of that size back to the kernel: for
// ꟻLIP at 256², called between other work (a GA scores hundreds of renders), the faults were
// more than half the time. Objects go back on the shelf when their Shelved handle dies and are
// taken again, in any thread; the shelf holds at most as many as were in use at once.
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace matevo::detail {

template <typename T>
class ScratchShelf {
public:
    // Owns a T while in use and puts it back on its shelf when destroyed.
    class Shelved {
    public:
        Shelved(ScratchShelf& shelf, std::unique_ptr<T> object)
            : shelf_(&shelf), object_(std::move(object)) {}
        Shelved(Shelved&&) noexcept = default;
        Shelved& operator=(Shelved&&) = delete;  // would drop the object it held
        ~Shelved() {
            if (object_) shelf_->putBack(std::move(object_));
        }
        T& operator*() const { return *object_; }
        T* operator->() const { return object_.get(); }

    private:
        ScratchShelf* shelf_;
        std::unique_ptr<T> object_;
    };

    // One from the shelf, as it was left, or a new one.
    Shelved take() {
        std::lock_guard lock(mutex_);
        if (objects_.empty()) return {*this, std::make_unique<T>()};
        Shelved taken{*this, std::move(objects_.back())};
        objects_.pop_back();
        return taken;
    }

private:
    void putBack(std::unique_ptr<T> object) {
        std::lock_guard lock(mutex_);
        objects_.push_back(std::move(object));
    }

    std::mutex mutex_;
    std::vector<std::unique_ptr<T>> objects_;
};

}  // namespace matevo::detail
