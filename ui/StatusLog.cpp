#include "StatusLog.h"

#include <chrono>
#include <ctime>
#include <utility>

namespace matevo::ui {
namespace {

std::string clockTime() {
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm local{};
    localtime_r(&now, &local);
    char text[16];
    std::strftime(text, sizeof text, "%H:%M:%S", &local);
    return text;
}

}  // namespace

void StatusLog::post(std::string text, StatusKind kind) {
    entries_.push_back({clockTime(), kind, std::move(text)});
    if (entries_.size() > kKeptEntries) entries_.erase(entries_.begin());
}

const StatusEntry& StatusLog::latest() const {
    static const StatusEntry kNothing;
    return entries_.empty() ? kNothing : entries_.back();
}

}  // namespace matevo::ui
