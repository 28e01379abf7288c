#include "gpu/ValidationLog.h"

namespace matevo::gpu {

void ValidationLog::addError(std::string message) {
    std::lock_guard lock(mutex_);
    ++errors_;
    keep("error: " + std::move(message));
}

void ValidationLog::addWarning(std::string message) {
    std::lock_guard lock(mutex_);
    ++warnings_;
    keep("warning: " + std::move(message));
}

int ValidationLog::errorCount() const {
    std::lock_guard lock(mutex_);
    return errors_;
}

int ValidationLog::warningCount() const {
    std::lock_guard lock(mutex_);
    return warnings_;
}

std::vector<std::string> ValidationLog::messages() const {
    std::lock_guard lock(mutex_);
    return messages_;
}

void ValidationLog::keep(std::string message) {
    if (messages_.size() < kKeptMessages) messages_.push_back(std::move(message));
}

}  // namespace matevo::gpu
