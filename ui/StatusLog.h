#pragma once
// What the editor tells the user: every file action, error, clamp and adjustment, newest last.
// The status bar shows the newest in full; the log window lists the recent ones.
#include <cstddef>
#include <string>
#include <vector>

namespace matevo::ui {

enum class StatusKind { Info, Warning, Error };

struct StatusEntry {
    std::string time;  // local wall-clock "HH:MM:SS", for the log
    StatusKind kind = StatusKind::Info;
    std::string text;
};

class StatusLog {
public:
    static constexpr std::size_t kKeptEntries = 200;

    void post(std::string text, StatusKind kind = StatusKind::Info);
    // Empty text when nothing was posted yet.
    const StatusEntry& latest() const;
    const std::vector<StatusEntry>& entries() const { return entries_; }

private:
    std::vector<StatusEntry> entries_;
};

}  // namespace matevo::ui
